#include "time_chart.h"

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QResizeEvent>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "chart_style.h"
#include "marker_overlay.h"
#include "series_points.h"

namespace fooball::gui {
namespace {

/// px of plot height per value tick interval, and the most intervals: labels never crowd.
constexpr double kPixelsPerValueTick = 32.0;
constexpr int kMaxValueTicks = 6;
/// px of plot height at least: five value tick intervals, a plot one can read values off.
constexpr double kMinPlotHeight = 5.0 * kPixelsPerValueTick;
/// px Qt Charts puts around the title, the legend, the plot and each axis' labels and title,
/// beyond their fonts' heights (measured on Qt 6.4 in screenshots: with less, it elides the
/// labels and titles to "…").
constexpr double kLayoutSpacing = 46.0;
constexpr double kAxisTitleSpacing = 8.0;

void applyScale(QLogValueAxis* axis, const LogAxisScale& scale) {
  // Labels sit at the powers of the base: a base of 10^k labels every k-th decade. As with a
  // linear axis' interval, the base grows before the range and shrinks after it, so no layout
  // in between has a label per decade over a range of hundreds of decades.
  const double base = std::pow(10.0, scale.decadesPerTick);
  if (base >= axis->base()) {
    axis->setBase(base);
    axis->setRange(scale.min(), scale.max());
  } else {
    axis->setRange(scale.min(), scale.max());
    axis->setBase(base);
  }
}

}  // namespace

TimeChart::TimeChart(const QString& title, std::vector<Quantity> quantities,
                     const std::deque<ChartMarker>* markers, ValueAxisKind valueAxisKind,
                     QWidget* parent)
    // The chart goes to the view's constructor, which owns it from then on. QChartView(parent)
    // would make a default chart of its own that a later setChart() takes out of the scene but
    // leaves to us to delete (30 kB lost per chart, found by LeakSanitizer).
    : QChartView(new QChart, parent),
      chart_(QChartView::chart()),
      timeAxis_(new QValueAxis(chart_)),
      quantities_(std::move(quantities)) {
  if (valueAxisKind == ValueAxisKind::Logarithmic) {
    logAxis_ = new QLogValueAxis(chart_);
    valueAxis_ = logAxis_;
  } else {
    linearAxis_ = new QValueAxis(chart_);
    valueAxis_ = linearAxis_;
  }
  styleChart(chart_, title, font());
  chart_->setMargins(kChartMargins);

  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(valueAxis_, Qt::AlignLeft);
  styleAxis(timeAxis_, font());
  if (linearAxis_ != nullptr) styleAxis(linearAxis_, font());
  if (logAxis_ != nullptr) {
    styleAxis(static_cast<QAbstractAxis*>(logAxis_), font());
    logAxis_->setMinorTickCount(0);
    // "1e-09", "0.001", "1", "1000": short, and exact at powers of ten.
    logAxis_->setLabelFormat(QStringLiteral("%g"));
    applyScale(logAxis_, LogAxisScale{});
  }
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
    if (valueTicksFor(plotArea) != valueTicks_ && fitValueAxis()) showCurves();
  });
}

void TimeChart::setOwners(const std::vector<CurveOwner>& owners, bool colourByRun) {
  // Attaching a series resets an axis' range to its domain's, whatever the tick interval: from
  // a residual axis ticked every 1e-12 J to a range of 1 that is 10¹² tick items (the window
  // hung there). A fixed tick count is safe until the next redraw sets a range and interval.
  timeAxis_->setTickType(QValueAxis::TicksFixed);
  if (linearAxis_ != nullptr) linearAxis_->setTickType(QValueAxis::TicksFixed);
  removeAllSeries();
  valueScale_.reset();
  logValueScale_.reset();
  colourByRun_ = colourByRun;
  bool hasBaseline = false;
  for (const CurveOwner& owner : owners) {
    const bool baseline = owner.run == ChartData::kBaseline;
    hasBaseline = hasBaseline || baseline;
    for (const Quantity quantity : quantities_) {
      const QString name = quantities_.size() > 1 && (baseline || !colourByRun)
                               ? owner.label + QStringLiteral(" · ") + quantityName(quantity)
                               : owner.label;
      const QPen pen = baseline ? baselinePen() : curvePen(quantity, owner.run, colourByRun);
      Curve curve{quantity, owner.run, addSeries(name, pen), {}};
      curve.points.reserve(kMaxPointsPerCurve);
      curves_.push_back(std::move(curve));
    }
  }
  if (colourByRun && quantities_.size() > 1) {
    for (const Quantity quantity : quantities_) {
      QPen stylePen = curvePen(quantity, 0, true);
      stylePen.setColor(chart_colours::kLabel);
      legendKeys_.push_back({addSeries(quantityName(quantity), stylePen), quantity});
    }
  }
  if (hasBaseline) {
    legendKeys_.push_back(
        {addSeries(tr("chaos baseline: run 0 with every ball moved 1e-9 m"), baselinePen()),
         std::nullopt});
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
  bool anyEntry = false;
  const auto setLegendEntryShown = [legend, &anyEntry](QLineSeries* series, bool shown) {
    for (QLegendMarker* marker : legend->markers(series))
      marker->setVisible(shown);
    anyEntry = anyEntry || shown;
  };
  // A series' visibility resets its legend entry, so the entry is set after it.
  for (Curve& curve : curves_) {
    const bool shown = isShown(curve.quantity);
    curve.series->setVisible(shown);
    // Single-run colours name each curve; in compare mode the keys below do, and the baseline
    // has a key of its own either way.
    const bool named = !colourByRun_ && curve.run != ChartData::kBaseline;
    setLegendEntryShown(curve.series, shown && named);
    if (!shown) {
      curve.points.clear();
      curve.series->clear();
    }
  }
  for (const LegendKey& key : legendKeys_) {
    setLegendEntryShown(key.series, key.quantity ? isShown(*key.quantity) : showsAnyQuantity());
  }
  // An empty legend gives its row back to the plot. (Not from the markers' isVisible(): a
  // hidden legend's markers all say false.)
  legend->setVisible(anyEntry);
  updateMinimumHeight();
}

bool TimeChart::showsAnyQuantity() const {
  return std::any_of(quantities_.begin(), quantities_.end(),
                     [this](Quantity quantity) { return isShown(quantity); });
}

void TimeChart::setValueAxisTitle(const QString& name, const QString& unit) {
  valueName_ = name;
  valueUnit_ = unit;
  updateValueAxisTitle();
}

void TimeChart::updateValueAxisTitle() {
  const QString title =
      valueName_ + QString::fromStdString(unitSuffix(valueUnit_.toStdString(), displayExponent_));
  if (title == valueAxis_->titleText()) return;
  valueAxis_->setTitleText(title);
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
  const double legendHeight = chart_->legend()->isVisible() ? legend.height() : 0.0;
  double height = kChartMargins.top() + kChartMargins.bottom() + title.height() + legendHeight +
                  plot + tickLabels.height() + axisTitle.height() + kLayoutSpacing;
  setMinimumHeight(static_cast<int>(std::ceil(height)));
}

void TimeChart::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  setMinimumWidth(static_cast<int>(std::ceil(chart_->minimumSize().width())));
}

void TimeChart::setMarkerLabelsShown(bool shown) {
  markerOverlay_->setLabelsShown(shown);
}

void TimeChart::forgetValueScale() {
  valueScale_.reset();
  logValueScale_.reset();
}

void TimeChart::redraw(std::span<const SampleHistory* const> histories,
                       const SampleHistory* baseline, const AxisScale& timeScale) {
  const int maxPoints = maxPointsPerCurve();
  ValueRange shownValues;
  for (Curve& curve : curves_) {
    if (!isShown(curve.quantity)) continue;
    const SampleHistory* history = nullptr;
    if (curve.run == ChartData::kBaseline) {
      history = baseline;
    } else if (curve.run >= 0 && static_cast<std::size_t>(curve.run) < histories.size()) {
      history = histories[static_cast<std::size_t>(curve.run)];
    }
    if (history != nullptr) {
      shownValues.include(fillSeriesPoints(*history, curve.quantity, timeScale.min, timeScale.max,
                                           maxPoints, curve.points, logarithmic()));
    } else {
      curve.points.clear();
    }
    // Qt rebuilds a curve's geometry (and strokes its outline) on every change of its points
    // or of an axis: empty while the axes change, each curve is built once, by replace().
    curve.series->clear();
  }
  applyScale(timeAxis_, timeScale, QString::fromStdString(tickLabelFormat(timeScale)));
  shownValues_ = shownValues;
  fitValueAxis();
  showCurves();
  markerOverlay_->update();
}

void TimeChart::showCurves() {
  const double unit = std::pow(10.0, displayExponent_);
  for (Curve& curve : curves_) {
    if (!isShown(curve.quantity)) continue;
    if (displayExponent_ == 0) {
      curve.series->replace(curve.points);
      continue;
    }
    scaledPoints_.clear();
    scaledPoints_.reserve(curve.points.size());
    for (const QPointF& point : curve.points)
      scaledPoints_.append(QPointF(point.x(), point.y() / unit));
    curve.series->replace(scaledPoints_);
  }
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

bool TimeChart::fitValueAxis() {
  const int ticks = valueTicksFor(chart_->plotArea());
  if (ticks != valueTicks_) forgetValueScale();
  valueTicks_ = ticks;
  if (logAxis_ != nullptr) {
    logValueScale_ = followLogValues(shownValues_, logValueScale_, ticks);
    applyScale(logAxis_, *logValueScale_);
  } else {
    valueScale_ = followValues(shownValues_, valueScale_, ticks);
    const int exponent = displayExponent(*valueScale_);
    // Whole-number or half ticks in these units (displayExponent): one decimal at most.
    const AxisScale shown = inDisplayUnits(*valueScale_, exponent);
    applyScale(linearAxis_, shown,
               shown.tickInterval >= 1.0 ? QStringLiteral("%.0f") : QStringLiteral("%.1f"));
    if (exponent != displayExponent_) {
      displayExponent_ = exponent;
      updateValueAxisTitle();
      return true;
    }
  }
  return false;
}

int TimeChart::pointCount(int run) const {
  int count = 0;
  for (const Curve& curve : curves_) {
    if (curve.run == run && isShown(curve.quantity)) {
      count = std::max(count, static_cast<int>(curve.series->count()));
    }
  }
  return count;
}

const TimeChart::Curve* TimeChart::findCurve(int run, int quantityIndex) const {
  if (quantityIndex < 0 || static_cast<std::size_t>(quantityIndex) >= quantities_.size()) {
    return nullptr;
  }
  const Quantity quantity = quantities_[static_cast<std::size_t>(quantityIndex)];
  for (const Curve& curve : curves_) {
    if (curve.run == run && curve.quantity == quantity) return &curve;
  }
  return nullptr;
}

QList<QPointF> TimeChart::points(int run, int quantityIndex) const {
  const Curve* curve = findCurve(run, quantityIndex);
  if (curve == nullptr || !isShown(curve->quantity)) return {};
  return curve->series->points();
}

QPen TimeChart::pen(int run, int quantityIndex) const {
  const Curve* curve = findCurve(run, quantityIndex);
  return curve != nullptr ? curve->series->pen() : QPen(Qt::NoPen);
}

QString TimeChart::valueAxisTitle() const {
  return valueAxis_->titleText();
}

QStringList TimeChart::valueTickLabels() const {
  // Qt Charts draws each label as a text item of its own; the value axis' are the ones beside
  // the plot on the left, upright (its title there runs up the side).
  const QRectF plot = chart_->plotArea();
  std::vector<std::pair<double, QString>> labels;
  for (const QGraphicsItem* item : chart_->scene()->items()) {
    const auto* text = qgraphicsitem_cast<const QGraphicsTextItem*>(item);
    if (text == nullptr || !text->isVisible()) continue;
    const QPointF centre = text->sceneBoundingRect().center();
    const bool beside = centre.x() < plot.left() && centre.y() >= plot.top() - 1.0 &&
                        centre.y() <= plot.bottom() + 1.0;
    if (beside && text->rotation() == 0.0) labels.emplace_back(centre.y(), text->toPlainText());
  }
  std::sort(labels.begin(), labels.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  QStringList texts;
  for (const auto& label : labels)
    texts.append(label.second);
  return texts;
}

std::pair<double, double> TimeChart::valueRange() const {
  if (logAxis_ != nullptr) return {logAxis_->min(), logAxis_->max()};
  return {linearAxis_->min(), linearAxis_->max()};
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
