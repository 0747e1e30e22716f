#include "wall_containment.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fooball::chipmunk_detail {

namespace {

/// What bringing back one axis of one ball did.
struct AxisReturn {
  bool brought = false;
  double depth = 0.0;    ///< m, how far beyond the face the centre was
  double impulse = 0.0;  ///< N·s per kg, |Δv|
};

/// One axis against the faces at `low` and `high` (m; ±∞ where a wall is off), with gravity's
/// component `g` (m/s²) along it.
AxisReturn bringBackAxis(double& position, double& velocity, double low, double high, double g) {
  double face;
  double inward;  // +1 at the low face, −1 at the high one
  if (position < low) {
    face = low;
    inward = 1.0;
  } else if (position > high) {
    face = high;
    inward = -1.0;
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
    // Too little energy to climb back to the mirror point (a long step under strong gravity
    // carried it deep: semi-implicit Euler's own loss). It stops at the apex of its bounce,
    // p − v²/(2g), or on the face if even that lies beyond it.
    const double apex = position - velocity * velocity / (2.0 * g);
    position = std::clamp(apex, std::min(face, mirrored), std::max(face, mirrored));
    velocity = 0.0;
  }
  return {true, depth, std::abs(velocity - before)};
}

}  // namespace

WallContainment::WallContainment(const Box& box, const Walls& walls, Vec2 gravity, double thickness)
    : gravity_(gravity), thickness_(thickness) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  lowX_ = walls.left ? 0.0 : -kNone;
  highX_ = walls.right ? box.width : kNone;
  lowY_ = walls.bottom ? 0.0 : -kNone;
  highY_ = walls.top ? box.height : kNone;
}

void WallContainment::bringBack(cpBody* ball, double radius, double mass) {
  cpVect p = cpBodyGetPosition(ball);
  cpVect v = cpBodyGetVelocity(ball);
  const AxisReturn x = bringBackAxis(p.x, v.x, lowX_, highX_, gravity_.x);
  const AxisReturn y = bringBackAxis(p.y, v.y, lowY_, highY_, gravity_.y);
  cpBodySetPosition(ball, p);
  cpBodySetVelocity(ball, v);
  ++ballsBroughtBack_;
  const double unseen = radius + 2.0 * thickness_;  // m
  for (const AxisReturn& axis : {x, y}) {
    if (!axis.brought) continue;
    impulse_ += mass * axis.impulse;
    if (axis.depth > unseen) ++wallCollisions_;
  }
}

}  // namespace fooball::chipmunk_detail
