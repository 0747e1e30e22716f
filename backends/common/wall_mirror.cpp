#include "wall_mirror.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fooball::common {

namespace {

/// One axis against the faces at `low` and `high` (m; ±∞ where a wall is off), with gravity's
/// component `g` (m/s²) along it.
WallMirror::AxisReturn bringBackAxis(double& position, double& velocity, double low, double high,
                                     double g, WallBit lowWall, WallBit highWall) {
  double face;
  double inward;  // +1 at the low face, −1 at the high one
  WallBit wall;
  if (position < low) {
    face = low;
    inward = 1.0;
    wall = lowWall;
  } else if (position > high) {
    face = high;
    inward = -1.0;
    wall = highWall;
  } else {
    return {};
  }
  const double depth = std::abs(position - face);
  const double before = velocity;
  // Beyond both faces' span only at absurd speeds: then on the far face.
  const double mirrored = std::clamp(2.0 * face - position, low, high);
  // ½v'² − g·p' = ½v² − g·p (per kg, along this axis): the energy the ball has.
  const double speedSquared = velocity * velocity + 2.0 * g * (mirrored - position);
  if (g == 0.0) {
    position = mirrored;
    velocity = inward * std::abs(velocity);
  } else if (speedSquared >= 0.0) {
    position = mirrored;
    velocity = inward * std::sqrt(speedSquared);
  } else {
    const double apex = position - velocity * velocity / (2.0 * g);
    position = std::clamp(apex, std::min(face, mirrored), std::max(face, mirrored));
    velocity = 0.0;
  }
  return {true, before * inward < 0.0, depth, std::abs(velocity - before), wall};
}

}  // namespace

WallMirror::WallMirror(const Box& box, const Walls& walls, Vec2 gravity) : gravity_(gravity) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  lowX_ = walls.left ? 0.0 : -kNone;
  highX_ = walls.right ? box.width : kNone;
  lowY_ = walls.bottom ? 0.0 : -kNone;
  highY_ = walls.top ? box.height : kNone;
}

WallMirror::Return WallMirror::bringBack(Vec2& position, Vec2& velocity) const {
  return {bringBackAxis(position.x, velocity.x, lowX_, highX_, gravity_.x, kLeftWall, kRightWall),
          bringBackAxis(position.y, velocity.y, lowY_, highY_, gravity_.y, kBottomWall, kTopWall)};
}

}  // namespace fooball::common
