#pragma once

#include "common/wall_touches.h"
#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball::common {

/// Brings back a ball whose centre an engine's step left beyond a wall that is on, as an elastic
/// wall would have: its centre mirrored in the wall's face, its velocity across the wall turned
/// inwards. The engine adapters whose engine can leave a centre there (Chipmunk, Bullet; each
/// says why in its wall_containment.h) read and write their bodies and count; the geometry and
/// the energy are here.
///
/// Mirroring moves the ball against gravity by twice its depth, so the speed across the wall it
/// leaves with pays for that lift (½v'² = ½v² + g·Δp per axis, per kg): the energy an exact wall
/// keeps. If the lift costs more than the ball has (a long step under strong gravity carried it
/// deep: semi-implicit Euler's own loss), it stops at the apex of its bounce, p − v²/(2g), or on
/// the face if even that lies beyond it.
class WallMirror {
 public:
  /// `gravity` (m/s²) as the step flies the balls.
  WallMirror(const Box& box, const Walls& walls, Vec2 gravity);

  /// Whether the centre `x`, `y` (m) is where no wall sends it back: the usual case, four
  /// comparisons.
  bool inside(double x, double y) const {
    return x >= lowX_ && x <= highX_ && y >= lowY_ && y <= highY_;
  }

  /// What bringing back one axis of one ball did.
  struct AxisReturn {
    bool brought = false;      ///< the centre was beyond a face on this axis
    bool leaving = false;      ///< its velocity still pointed out of the box: it bounced here
    double depth = 0.0;        ///< m, how far beyond the face the centre was
    double impulse = 0.0;      ///< N·s per kg, |Δv|
    WallBit wall = kLeftWall;  ///< the wall whose face it was beyond (when brought)
  };
  struct Return {
    AxisReturn x;
    AxisReturn y;
  };

  /// Brings `position` (m) and `velocity` (m/s) back on each axis whose face the centre is
  /// beyond.
  Return bringBack(Vec2& position, Vec2& velocity) const;

 private:
  double lowX_;   ///< m, the lowest centre left alone (−∞ where the wall is off)
  double highX_;  ///< m, the highest
  double lowY_;
  double highY_;
  Vec2 gravity_;  ///< m/s²
};

}  // namespace fooball::common
