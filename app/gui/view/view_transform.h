#pragma once

#include <QPointF>
#include <QRect>

#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball::gui {

/// The one metres → pixels mapping of a view: the box [0,w] × [0,h] (y up) fitted into an
/// area of the widget with its aspect ratio kept, centred, y flipped.
class ViewTransform {
 public:
  ViewTransform() = default;
  /// Fits `box` into `area` (widget pixels) leaving `margin` pixels on every side.
  ViewTransform(const Box& box, const QRect& area, int margin);

  /// px/m
  double scale() const { return scale_; }
  /// Where the box lies in widget pixels (whole pixels, so a ball image maps 1:1).
  QRect boxRect() const { return boxRect_; }

  QPointF toPixels(Vec2 metres) const {
    return {boxRect_.left() + metres.x * scale_, boxRect_.top() + (height_ - metres.y) * scale_};
  }
  Vec2 toMetres(QPointF pixels) const {
    return {(pixels.x() - boxRect_.left()) / scale_,
            height_ - (pixels.y() - boxRect_.top()) / scale_};
  }
  double toPixels(double metres) const { return metres * scale_; }
  double toMetres(double pixels) const { return pixels / scale_; }

 private:
  double scale_ = 1.0;
  double height_ = 1.0;  ///< m
  QRect boxRect_;
};

}  // namespace fooball::gui
