#include "wall_containment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plane_vectors.h"

namespace fooball::bullet_detail {

namespace {

/// What bringing back one axis of one ball did.
struct AxisReturn {
  bool bouncedHere = false;  ///< its velocity pointed out of the box
  double impulse = 0.0;      ///< N·s per kg, |Δv|
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
  const double before = velocity;
  // Beyond both faces' span only at absurd speeds: then on the far face.
  const double mirrored = std::clamp(2.0 * face - position, low, high);
  // ½v'² − g·p' = ½v² − g·p (per kg, along this axis): the energy the ball has.
  const double speedSquared = velocity * velocity + 2.0 * g * (mirrored - position);
  if (speedSquared >= 0.0) {
    position = mirrored;
    velocity = inward * std::sqrt(speedSquared);
  } else {
    // Too little energy to climb back to the mirror point: it stops at the apex of its bounce,
    // p − v²/(2g), or on the face if even that lies beyond it.
    const double apex = position - velocity * velocity / (2.0 * g);
    position = std::clamp(apex, std::min(face, mirrored), std::max(face, mirrored));
    velocity = 0.0;
  }
  return {before * inward < 0.0, std::abs(velocity - before)};
}

}  // namespace

WallContainment::WallContainment(const Box& box, const Walls& walls, Vec2 gravity)
    : gravity_(gravity) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  lowX_ = walls.left ? 0.0 : -kNone;
  highX_ = walls.right ? box.width : kNone;
  lowY_ = walls.bottom ? 0.0 : -kNone;
  highY_ = walls.top ? box.height : kNone;
}

void WallContainment::bringBack(btRigidBody& ball, double mass) {
  Vec2 p = fromBullet(ball.getWorldTransform().getOrigin());
  Vec2 v = fromBullet(ball.getLinearVelocity());
  const AxisReturn x = bringBackAxis(p.x, v.x, lowX_, highX_, gravity_.x);
  const AxisReturn y = bringBackAxis(p.y, v.y, lowY_, highY_, gravity_.y);
  btTransform transform = ball.getWorldTransform();
  transform.setOrigin(toBullet(p));
  ball.setWorldTransform(transform);
  ball.setLinearVelocity(toBullet(v));
  ++ballsBroughtBack_;
  for (const AxisReturn& axis : {x, y}) {
    impulse_ += mass * axis.impulse;
    if (axis.bouncedHere) ++wallCollisions_;
  }
}

}  // namespace fooball::bullet_detail
