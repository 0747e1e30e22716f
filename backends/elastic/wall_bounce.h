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

/// Reflects a ball that has crossed a wall that is on, exactly under constant gravity: the time
/// since it crossed comes from the quadratic of its flight, and it is reflected there and flown
/// back to now (through as many bounces as fit, off either wall of the axis). So the energy along
/// each axis, ½v² − g·p, is kept to rounding in any direction of gravity. (A mirror of the
/// overshoot with the speed set to keep the energy puts a slow ball higher than its energy
/// reaches, and then gains energy.) Drag is left out of the time since the crossing: at most one
/// substep, in which drag changes the speed by a fraction c·h.
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
