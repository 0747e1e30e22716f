#pragma once

#include <QGraphicsItem>
#include <deque>

#include "chart_data.h"

class QChart;
class QValueAxis;

namespace fooball::gui {

/// Draws the markers over a chart's plot area: a faint vertical line at each marker's time and,
/// where there is room, its label near the top. A scene item, so it appears on screen and in
/// every rendering of the chart (PNG export) alike.
class MarkerOverlay : public QGraphicsItem {
 public:
  /// `chart` becomes the parent item; `timeAxis` and `markers` must outlive the overlay.
  MarkerOverlay(QChart* chart, const QValueAxis* timeAxis, const std::deque<ChartMarker>* markers);

  /// Labels on one chart of a stack are enough; the others show the lines only.
  void setLabelsShown(bool shown);
  /// Markers inside the time axis's range: the ones drawn.
  int visibleCount() const;
  /// Call when the chart's plot area moved or resized.
  void plotAreaChanged();

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  QChart* chart_;
  const QValueAxis* timeAxis_;
  const std::deque<ChartMarker>* markers_;
  bool labelsShown_ = false;
};

}  // namespace fooball::gui
