#include "speed_histogram_chart.h"

#include <QAreaSeries>
#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>
#include <algorithm>

#include "chart_style.h"
#include "run_palette.h"

namespace fooball::gui {
namespace {

/// Tick intervals on the count axis: the dock is a strip, about 120 px of plot high.
constexpr int kCountTicks = 4;
/// The fill's opacity under an outline: one run's reads as a solid shape, eight overlaid still
/// let the ones below show through.
constexpr int kSingleFillAlpha = 0x50;
constexpr int kOverlaidFillAlpha = 0x24;

}  // namespace

SpeedHistogramChart::SpeedHistogramChart(QWidget* parent)
    // The chart goes to the view's constructor, which owns it (see TimeChart's).
    : QChartView(new QChart, parent),
      chart_(QChartView::chart()),
      speedAxis_(new QValueAxis(chart_)),
      countAxis_(new QValueAxis(chart_)),
      curve_(new QLineSeries(chart_)) {
  // No title: the dock's says it, and a strip 150 px high needs the room for the plot.
  styleChart(chart_, QString(), font());
  chart_->setMargins(kChartMargins);
  chart_->addAxis(speedAxis_, Qt::AlignBottom);
  chart_->addAxis(countAxis_, Qt::AlignLeft);
  styleAxis(speedAxis_, font());
  styleAxis(countAxis_, font());
  speedAxis_->setTitleText(tr("speed (m/s)"));
  countAxis_->setTitleText(tr("balls per bin"));
  setRenderHint(QPainter::Antialiasing);
  setFrameShape(QFrame::NoFrame);
}

void SpeedHistogramChart::setRuns(const QStringList& labels, const QString& curveName) {
  // Attaching a series resets the axes' ranges: fixed ticks until the next draw (applyScale).
  speedAxis_->setTickType(QValueAxis::TicksFixed);
  countAxis_->setTickType(QValueAxis::TicksFixed);
  countScale_.reset();
  for (QAreaSeries* histogram : histograms_) {
    chart_->removeSeries(histogram);
    delete histogram;
  }
  histograms_.clear();
  if (chart_->series().contains(curve_)) chart_->removeSeries(curve_);

  const int alpha = labels.size() > 1 ? kOverlaidFillAlpha : kSingleFillAlpha;
  for (int run = 0; run < labels.size(); ++run) {
    auto* outline = new QLineSeries;
    auto* histogram = new QAreaSeries(outline);
    outline->setParent(histogram);
    histogram->setName(labels[run]);
    chart_->addSeries(histogram);
    histogram->attachAxis(speedAxis_);
    histogram->attachAxis(countAxis_);
    // After addSeries, which applies the theme's colours. One-pixel outlines: Qt draws those
    // directly.
    QColor fill = colours::runColour(run);
    fill.setAlpha(alpha);
    histogram->setPen(QPen(colours::runColour(run), 1.0));
    histogram->setBrush(fill);
    histograms_.push_back(histogram);
  }
  // The curve last, so it lies over every histogram.
  curve_->setName(curveName);
  chart_->addSeries(curve_);
  curve_->attachAxis(speedAxis_);
  curve_->attachAxis(countAxis_);
  QPen curvePen(chart_colours::kTitle, 1.5);
  curvePen.setDashPattern({4.0, 2.0});
  curve_->setPen(curvePen);
  // The legend's swatches in the runs' full colours: the fills' faint ones read as black there.
  // With more runs than one the table under the chart names each in its colour, and a legend of
  // eight names beside the box would be cut to "el…": only the curve's entry stays.
  const bool runsInLegend = histograms_.size() == 1;
  for (std::size_t run = 0; run < histograms_.size(); ++run) {
    for (QLegendMarker* marker : chart_->legend()->markers(histograms_[run])) {
      marker->setShape(QLegend::MarkerShapeRectangle);
      marker->setBrush(colours::runColour(static_cast<int>(run)));
      marker->setVisible(runsInLegend);
    }
  }
}

void SpeedHistogramChart::draw(std::span<const SpeedHistogram* const> histograms,
                               std::span<const double> expected, const AxisScale& speedScale) {
  ValueRange counts;
  counts.include(0.0);
  const std::size_t shown = std::min(histograms.size(), histograms_.size());
  for (std::size_t run = 0; run < shown; ++run) {
    const SpeedHistogram& histogram = *histograms[run];
    points_.clear();
    for (std::size_t k = 0; k < histogram.counts.size(); ++k) {
      const double count = static_cast<double>(histogram.counts[k]);
      points_.append({static_cast<double>(k) * histogram.binWidth, count});
      points_.append({static_cast<double>(k + 1) * histogram.binWidth, count});
      counts.include(count);
    }
    histograms_[run]->upperSeries()->replace(points_);
  }
  points_.clear();
  const double binWidth = histograms.empty() ? 0.0 : histograms.front()->binWidth;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    points_.append({(static_cast<double>(k) + 0.5) * binWidth, expected[k]});
    counts.include(expected[k]);
  }
  curve_->replace(points_);

  applyScale(speedAxis_, speedScale, QStringLiteral("%g"));
  countScale_ = followValues(counts, countScale_, kCountTicks);
  applyScale(countAxis_, *countScale_, QStringLiteral("%g"));
  speedAxis_->setTitleText(tr("speed (m/s), bins of %1 m/s").arg(binWidth, 0, 'g', 3));
}

QList<QPointF> SpeedHistogramChart::histogramPoints(int run) const {
  return histograms_.at(static_cast<std::size_t>(run))->upperSeries()->points();
}

QPen SpeedHistogramChart::histogramPen(int run) const {
  return histograms_.at(static_cast<std::size_t>(run))->pen();
}

QBrush SpeedHistogramChart::histogramBrush(int run) const {
  return histograms_.at(static_cast<std::size_t>(run))->brush();
}

QString SpeedHistogramChart::histogramName(int run) const {
  return histograms_.at(static_cast<std::size_t>(run))->name();
}

QList<QPointF> SpeedHistogramChart::curvePoints() const {
  return curve_->points();
}

std::pair<double, double> SpeedHistogramChart::speedRange() const {
  return {speedAxis_->min(), speedAxis_->max()};
}

std::pair<double, double> SpeedHistogramChart::countRange() const {
  return {countAxis_->min(), countAxis_->max()};
}

QString SpeedHistogramChart::speedAxisTitle() const {
  return speedAxis_->titleText();
}

}  // namespace fooball::gui
