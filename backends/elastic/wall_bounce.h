#pragma once

#include <cstdint>

#include "balls.h"
#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::elastic {

/// What the walls did to a run of balls.
struct WallTally {
  std::uint64_t bounces = 0;  ///< collisions begun (common/wall_touches.h)
  double impulse = 0.0;       ///< N·s, Σ|Δp|
};

/// Reflects a ball that has crossed a wall that is on, exactly under constant gravity: the time
/// since it crossed comes from the quadratic of its flight, and it is reflected there and flown
/// back to now (through as many bounces as fit, off either wall of the axis). So the energy along
/// each axis, ½v² − g·p, is kept to rounding in any direction of gravity. (A mirror of the
/// overshoot with the speed set to keep the energy puts a slow ball higher than its energy
/// reaches, and then gains energy.) Drag is left out of the time since the crossing: at most one
/// substep, in which drag changes the speed by a fraction c·h.
///
/// Bounces are counted by the rule of common/wall_touches.h: a ball the wall turns back again
/// while it still touches it (resting, or pressed by a pile) is in the collision it began.
class WallBounce {
 public:
  WallBounce(const Box& box, const Walls& walls, Vec2 gravity)
      : box_(box),
        x_{walls.left, walls.right, box.width, gravity.x, common::kLeftWall, common::kRightWall},
        y_{walls.bottom, walls.top, box.height, gravity.y, common::kBottomWall, common::kTopWall} {}

  /// `touches`: the walls the ball touches, kept beside it.
  void bounce(Ball& ball, common::WallTouches& touches, WallTally& tally) const {
    const double r = ball.radius;
    // Most balls touch no wall: two comparisons per axis, and the work out of line.
    if (!(ball.x >= r && ball.x <= x_.length - r))
      bounceAxis(ball.x, ball.vx, r, ball.mass, x_, touches, tally);
    if (!(ball.y >= r && ball.y <= y_.length - r))
      bounceAxis(ball.y, ball.vy, r, ball.mass, y_, touches, tally);
    if (touches != 0) touches = common::stillTouching(touches, {ball.x, ball.y}, r, box_);
  }

 private:
  /// One axis: walls at 0 (inward normal +1) and at `length` (inward normal −1).
  struct Axis {
    bool lowOn;
    bool highOn;
    double length;   ///< m
    double gravity;  ///< m/s², component along the axis
    common::WallBit lowWall;
    common::WallBit highWall;
  };

  static void bounceAxis(double& p, double& v, double r, double mass, const Axis& axis,
                         common::WallTouches& touches, WallTally& tally);

  Box box_;
  Axis x_;
  Axis y_;
};

}  // namespace fooball::elastic
