#include "time_chart.h"

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "chart_style.h"
#include "marker_overlay.h"
#include "series_points.h"

namespace fooball::gui {
namespace {

/// px around the plot: room for the last time label on the right.
const QMargins kChartMargins(4, 2, 12, 2);
/// px of plot height per value tick interval, and the most intervals: labels never crowd.
constexpr double kPixelsPerValueTick = 32.0;
constexpr int kMaxValueTicks = 6;
/// px of plot height at least: two value tick intervals.
constexpr double kMinPlotHeight = 2.0 * kPixelsPerValueTick;
/// px Qt Charts puts around the title, the legend, the plot and each axis' labels and title,
/// beyond their fonts' heights (measured on Qt 6.4 in screenshots: with less, it elides the
/// labels and titles to "…").
constexpr double kLayoutSpacing = 46.0;
constexpr double kAxisTitleSpacing = 8.0;

QFont sizedFont(const QFont& base, double pointSize, bool bold = false) {
  QFont font = base;
  font.setPointSizeF(pointSize);
  font.setBold(bold);
  return font;
}

void styleAxis(QValueAxis* axis, const QFont& baseFont) {
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0.0);
  axis->setLabelsFont(sizedFont(baseFont, 8.0));
  axis->setLabelsBrush(chart_colours::kLabel);
  axis->setTitleFont(sizedFont(baseFont, 8.0));
  axis->setTitleBrush(chart_colours::kLabel);
  // One-pixel pens: Qt draws those directly instead of stroking an outline each frame.
  axis->setGridLinePen(QPen(chart_colours::kGrid, 1.0));
  axis->setLinePen(QPen(chart_colours::kAxisLine, 1.0));
  axis->setMinorGridLineVisible(false);
  axis->setShadesVisible(false);
}

void applyScale(QValueAxis* axis, const AxisScale& scale) {
  // Every change relays the ticks out: in between, the new range must not meet the old, finer
  // interval (a range 10⁵ times wider would create 10⁵ tick items). Widen the interval before
  // the range, narrow it after.
  if (axis->tickType() != QValueAxis::TicksDynamic) {
    // Fixed ticks (see TimeChart::setRuns) are a handful whatever the range: set both, then
    // go back to ticks at round values.
    axis->setRange(scale.min, scale.max);
    axis->setTickInterval(scale.tickInterval);
    axis->setTickType(QValueAxis::TicksDynamic);
  } else if (scale.tickInterval >= axis->tickInterval()) {
    axis->setTickInterval(scale.tickInterval);
    axis->setRange(scale.min, scale.max);
  } else {
    axis->setRange(scale.min, scale.max);
    axis->setTickInterval(scale.tickInterval);
  }
  axis->setLabelFormat(QString::fromStdString(tickLabelFormat(scale)));
}

}  // namespace

TimeChart::TimeChart(const QString& title, std::vector<Quantity> quantities,
                     const std::deque<ChartMarker>* markers, QWidget* parent)
    // The chart goes to the view's constructor, which owns it from then on. QChartView(parent)
    // would make a default chart of its own that a later setChart() takes out of the scene but
    // leaves to us to delete (30 kB lost per chart, found by LeakSanitizer).
    : QChartView(new QChart, parent),
      chart_(QChartView::chart()),
      timeAxis_(new QValueAxis(chart_)),
      valueAxis_(new QValueAxis(chart_)),
      quantities_(std::move(quantities)) {
  // The theme first: it restyles everything already in the chart.
  chart_->setTheme(QChart::ChartThemeDark);
  chart_->setAnimationOptions(QChart::NoAnimation);
  chart_->setBackgroundBrush(chart_colours::kBackground);
  chart_->setBackgroundRoundness(0.0);
  chart_->setPlotAreaBackgroundBrush(chart_colours::kPlotArea);
  chart_->setPlotAreaBackgroundVisible(true);
  chart_->layout()->setContentsMargins(0, 0, 0, 0);
  chart_->setMargins(kChartMargins);
  chart_->setTitle(title);
  chart_->setTitleFont(sizedFont(font(), 9.0, true));
  chart_->setTitleBrush(chart_colours::kTitle);

  QLegend* legend = chart_->legend();
  legend->setAlignment(Qt::AlignTop);
  legend->setFont(sizedFont(font(), 8.0));
  legend->setLabelColor(chart_colours::kLabel);
  legend->setMarkerShape(QLegend::MarkerShapeFromSeries);

  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(valueAxis_, Qt::AlignLeft);
  styleAxis(timeAxis_, font());
  styleAxis(valueAxis_, font());
  timeAxis_->setTitleText(tr("time (s)"));

  setRenderHint(QPainter::Antialiasing);
  setFrameShape(QFrame::NoFrame);
  updateMinimumHeight();

  markerOverlay_ = new MarkerOverlay(chart_, timeAxis_, markers);
  connect(chart_, &QChart::plotAreaChanged, this, [this](const QRectF& plotArea) {
    // The margins now are the ones this layout used; setExtraMargins() may have changed
    // extraMargins_ since, for a layout still to come.
    const QMargins margins = chart_->margins();
    naturalPlotInsets_ = PlotInsets{
        plotArea.left() - (margins.left() - kChartMargins.left()),
        chart_->size().width() - plotArea.right() - (margins.right() - kChartMargins.right())};
    markerOverlay_->plotAreaChanged();
    // Qt elides tick labels that have no room: a plot that shrank gets fewer ticks.
    if (valueTicksFor(plotArea) != valueTicks_) fitValueAxis();
  });
}

void TimeChart::setRuns(const QStringList& runNames) {
  // Attaching a series resets an axis' range to its domain's, whatever the tick interval: from
  // a residual axis ticked every 1e-12 J to a range of 1 that is 10¹² tick items (the window
  // hung there). A fixed tick count is safe until the next redraw sets a range and interval.
  timeAxis_->setTickType(QValueAxis::TicksFixed);
  valueAxis_->setTickType(QValueAxis::TicksFixed);
  removeAllSeries();
  valueScale_.reset();
  const int runCount = static_cast<int>(runNames.size());
  for (int run = 0; run < runCount; ++run) {
    for (const Quantity quantity : quantities_) {
      const QString name = runCount > 1
                               ? runNames[run] + QStringLiteral(" · ") + quantityName(quantity)
                               : quantityName(quantity);
      Curve curve{quantity, run, addSeries(name, curvePen(quantity, run, runCount)), {}};
      curve.points.reserve(kMaxPointsPerCurve);
      curves_.push_back(std::move(curve));
    }
  }
  if (runCount > 1) {
    for (int run = 0; run < runCount; ++run) {
      legendKeys_.push_back({addSeries(runNames[run], QPen(runColour(run), 3.0)), std::nullopt});
    }
    for (const Quantity quantity : quantities_) {
      QPen stylePen = curvePen(quantity, 0, runCount);
      stylePen.setColor(chart_colours::kLabel);
      legendKeys_.push_back({addSeries(quantityName(quantity), stylePen), quantity});
    }
  }
  applyShownQuantities();
}

QLineSeries* TimeChart::addSeries(const QString& name, const QPen& pen) {
  auto* series = new QLineSeries(chart_);
  series->setName(name);
  chart_->addSeries(series);
  series->attachAxis(timeAxis_);
  series->attachAxis(valueAxis_);
  series->setPen(pen);  // after addSeries, which applies the theme's colours
  return series;
}

void TimeChart::removeAllSeries() {
  for (const Curve& curve : curves_) {
    chart_->removeSeries(curve.series);
    delete curve.series;
  }
  curves_.clear();
  for (const LegendKey& key : legendKeys_) {
    chart_->removeSeries(key.series);
    delete key.series;
  }
  legendKeys_.clear();
}

bool TimeChart::isShown(Quantity quantity) const {
  return std::find(hiddenQuantities_.begin(), hiddenQuantities_.end(), quantity) ==
         hiddenQuantities_.end();
}

void TimeChart::setQuantityShown(Quantity quantity, bool shown) {
  if (isShown(quantity) == shown) return;
  std::erase(hiddenQuantities_, quantity);
  if (!shown) hiddenQuantities_.push_back(quantity);
  valueScale_.reset();
  applyShownQuantities();
}

void TimeChart::applyShownQuantities() {
  QLegend* legend = chart_->legend();
  const auto setLegendEntryShown = [legend](QLineSeries* series, bool shown) {
    for (QLegendMarker* marker : legend->markers(series))
      marker->setVisible(shown);
  };
  // A series' visibility resets its legend entry, so the entry is set after it.
  for (Curve& curve : curves_) {
    const bool shown = isShown(curve.quantity);
    curve.series->setVisible(shown);
    setLegendEntryShown(curve.series, shown && legendKeys_.empty());
    if (!shown) {
      curve.points.clear();
      curve.series->clear();
    }
  }
  for (const LegendKey& key : legendKeys_) {
    setLegendEntryShown(key.series, key.quantity ? isShown(*key.quantity) : showsAnyQuantity());
  }
}

bool TimeChart::showsAnyQuantity() const {
  return std::any_of(quantities_.begin(), quantities_.end(),
                     [this](Quantity quantity) { return isShown(quantity); });
}

void TimeChart::setValueAxisTitle(const QString& title) {
  valueAxis_->setTitleText(title);
  updateMinimumHeight();
}

void TimeChart::setTimeAxisLabelsShown(bool shown) {
  timeAxis_->setLabelsVisible(shown);
  timeAxis_->setTitleVisible(shown);
  updateMinimumHeight();
}

void TimeChart::updateMinimumHeight() {
  const QFontMetricsF title(chart_->titleFont());
  const QFontMetricsF legend(chart_->legend()->font());
  const QFontMetricsF tickLabels(timeAxis_->labelsFont());
  const QFontMetricsF axisTitle(valueAxis_->titleFont());
  // The value axis' title runs up the side of the plot: shorter, and Qt elides it.
  const double plot =
      std::max(kMinPlotHeight, axisTitle.horizontalAdvance(valueAxis_->titleText()) + 8.0);
  double height = kChartMargins.top() + kChartMargins.bottom() + title.height() + legend.height() +
                  plot + tickLabels.height() + kLayoutSpacing;
  if (timeAxis_->isTitleVisible()) height += axisTitle.height();
  setMinimumHeight(static_cast<int>(std::ceil(height)));
}

void TimeChart::setMarkerLabelsShown(bool shown) {
  markerOverlay_->setLabelsShown(shown);
}

void TimeChart::forgetValueScale() {
  valueScale_.reset();
}

void TimeChart::redraw(std::span<const SampleHistory* const> histories,
                       const AxisScale& timeScale) {
  const int maxPoints = maxPointsPerCurve();
  ValueRange shownValues;
  for (Curve& curve : curves_) {
    if (!isShown(curve.quantity)) continue;
    if (static_cast<std::size_t>(curve.runIndex) < histories.size()) {
      shownValues.include(fillSeriesPoints(*histories[curve.runIndex], curve.quantity,
                                           timeScale.min, timeScale.max, maxPoints, curve.points));
    } else {
      curve.points.clear();
    }
    // Qt rebuilds a curve's geometry (and strokes its outline) on every change of its points
    // or of an axis: empty while the axes change, each curve is built once, by replace().
    curve.series->clear();
  }
  applyScale(timeAxis_, timeScale);
  shownValues_ = shownValues;
  fitValueAxis();
  for (Curve& curve : curves_) {
    if (isShown(curve.quantity)) curve.series->replace(curve.points);
  }
  markerOverlay_->update();
}

int TimeChart::maxPointsPerCurve() const {
  // A lowest and a highest point per pixel column is all a line can show; until the first
  // layout the width is unknown.
  const QRectF plot = chart_->plotArea();
  if (plot.isEmpty()) return kMaxPointsPerCurve;
  return std::clamp(2 * static_cast<int>(plot.width()), kMinPointsPerCurve, kMaxPointsPerCurve);
}

int TimeChart::valueTicksFor(const QRectF& plotArea) {
  return std::clamp(static_cast<int>(plotArea.height() / kPixelsPerValueTick), 2, kMaxValueTicks);
}

void TimeChart::fitValueAxis() {
  const int ticks = valueTicksFor(chart_->plotArea());
  if (ticks != valueTicks_) valueScale_.reset();
  valueTicks_ = ticks;
  valueScale_ = followValues(shownValues_, valueScale_, ticks);
  applyScale(valueAxis_, *valueScale_);
}

int TimeChart::pointCount(int runIndex) const {
  int count = 0;
  for (const Curve& curve : curves_) {
    if (curve.runIndex == runIndex && isShown(curve.quantity)) {
      count = std::max(count, curve.series->count());
    }
  }
  return count;
}

int TimeChart::visibleMarkerCount() const {
  return markerOverlay_->visibleCount();
}

void TimeChart::setExtraMargins(PlotInsets pixels) {
  extraMargins_ = pixels;
  QMargins margins = kChartMargins;
  margins.setLeft(kChartMargins.left() + static_cast<int>(std::lround(pixels.left)));
  margins.setRight(kChartMargins.right() + static_cast<int>(std::lround(pixels.right)));
  chart_->setMargins(margins);
}

}  // namespace fooball::gui
