#include "marker_overlay.h"

#include <QChart>
#include <QFontMetricsF>
#include <QPainter>
#include <QValueAxis>
#include <cmath>
#include <vector>

#include "chart_style.h"
#include "marker_labels.h"

namespace fooball::gui {
namespace {

/// Labels stack in this many rows before one is left out for lack of room.
constexpr int kLabelRows = 2;
/// px between neighbouring labels in a row, and around a label's text.
constexpr double kLabelGap = 6.0;
constexpr double kLabelPadding = 2.0;

}  // namespace

MarkerOverlay::MarkerOverlay(QChart* chart, const QValueAxis* timeAxis,
                             const std::deque<ChartMarker>* markers)
    : QGraphicsItem(chart), chart_(chart), timeAxis_(timeAxis), markers_(markers) {
  // Above the curves: a marker explains what happens to them at that time.
  setZValue(100.0);
}

void MarkerOverlay::setLabelsShown(bool shown) {
  labelsShown_ = shown;
  update();
}

int MarkerOverlay::visibleCount() const {
  const double start = timeAxis_->min();
  const double end = timeAxis_->max();
  int count = 0;
  for (const ChartMarker& marker : *markers_) {
    if (marker.time >= start && marker.time <= end) ++count;
  }
  return count;
}

void MarkerOverlay::plotAreaChanged() {
  prepareGeometryChange();
}

QRectF MarkerOverlay::boundingRect() const {
  return chart_->plotArea();
}

void MarkerOverlay::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const QRectF plot = chart_->plotArea();
  const double start = timeAxis_->min();
  const double span = timeAxis_->max() - start;
  if (markers_->empty() || !(span > 0.0) || plot.isEmpty()) return;

  painter->save();
  painter->setClipRect(plot);
  const QPen linePen(chart_colours::kMarker, 1.0, Qt::DashLine);
  QFont labelFont = painter->font();
  labelFont.setPointSizeF(7.5);
  painter->setFont(labelFont);
  const QFontMetricsF metrics(labelFont);
  const double rowHeight = metrics.height() + 2.0 * kLabelPadding;

  double lastLineX = -1.0;
  std::vector<MarkerLabelRequest> requests;
  std::vector<const ChartMarker*> labelled;
  for (const ChartMarker& marker : *markers_) {
    if (marker.time < start || marker.time > start + span) continue;
    const double x = plot.left() + (marker.time - start) / span * plot.width();
    // Many markers within one pixel column (a drag) draw as one line.
    if (std::abs(x - lastLineX) >= 1.0) {
      painter->setPen(linePen);
      painter->drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
      lastLineX = x;
    }
    if (!labelsShown_ || marker.label.isEmpty()) continue;
    requests.push_back({x, metrics.horizontalAdvance(marker.label) + 2.0 * kLabelPadding});
    labelled.push_back(&marker);
  }
  const auto rects = layoutMarkerLabels(requests, plot, rowHeight, kLabelRows, kLabelGap);
  for (std::size_t i = 0; i < rects.size(); ++i) {
    if (!rects[i]) continue;
    painter->fillRect(*rects[i], chart_colours::kMarkerLabelBackground);
    painter->setPen(chart_colours::kLabel);
    painter->drawText(*rects[i], Qt::AlignCenter, labelled[i]->label);
  }
  painter->restore();
}

}  // namespace fooball::gui
