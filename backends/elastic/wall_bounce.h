#pragma once

#include <cstdint>

#include "balls.h"
#include "fooball/scene.h"

namespace fooball::elastic {

/// What the walls did to a run of balls.
struct WallTally {
  std::uint64_t bounces = 0;
  double impulse = 0.0;  ///< N·s, Σ|Δp|
};

/// Reflects a ball that has crossed a wall that is on. The position is mirrored back into the
/// box (exact for straight flight), and the outgoing normal speed is chosen so the mirror does
/// not change the energy under gravity: ½v'² = ½v² + (g·n)·2δ, where δ is the penetration. A
/// plain mirror would gain m·g·2δ on every floor bounce, and a ball would bounce ever higher.
class WallBounce {
 public:
  WallBounce(const Box& box, const Walls& walls, Vec2 gravity)
      : x_{walls.left, walls.right, box.width, gravity.x},
        y_{walls.bottom, walls.top, box.height, gravity.y} {}

  void bounce(Ball& ball, WallTally& tally) const {
    const double r = ball.radius;
    // Most balls touch no wall: two comparisons per axis, and the work out of line.
    if (!(ball.x >= r && ball.x <= x_.length - r))
      bounceAxis(ball.x, ball.vx, r, ball.mass, x_, tally);
    if (!(ball.y >= r && ball.y <= y_.length - r))
      bounceAxis(ball.y, ball.vy, r, ball.mass, y_, tally);
  }

 private:
  /// One axis: walls at 0 (inward normal +1) and at `length` (inward normal −1).
  struct Axis {
    bool lowOn;
    bool highOn;
    double length;   ///< m
    double gravity;  ///< m/s², component along the axis
  };

  static void bounceAxis(double& p, double& v, double r, double mass, const Axis& axis,
                         WallTally& tally);

  Axis x_;
  Axis y_;
};

}  // namespace fooball::elastic
