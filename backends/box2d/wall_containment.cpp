#include "wall_containment.h"

#include <cmath>
#include <limits>

namespace fooball::box2d_detail {

namespace {

/// One axis of one ball against the walls with faces at 0 and `side` (m), which leave alone a
/// centre in [lowest, highest]. Returns whether the ball was put back, and adds the impulse the
/// wall gave to `impulse`.
bool containAxis(float& position, float& velocity, double side, double lowest, double highest,
                 double mass, double& impulse) {
  const double p = static_cast<double>(position);
  double face;
  bool outward;
  if (p < lowest) {
    face = 0.0;
    outward = velocity < 0.0f;
  } else if (p > highest) {
    face = side;
    outward = velocity > 0.0f;
  } else {
    return false;
  }
  position = static_cast<float>(face);
  if (outward) {
    impulse += 2.0 * mass * std::abs(static_cast<double>(velocity));
    velocity = -velocity;
  }
  return true;
}

}  // namespace

WallContainment::WallContainment(const Box& box, const Walls& walls) : box_(box) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  lowest_ = {walls.left ? -kWallSlack : -kNone, walls.bottom ? -kWallSlack : -kNone};
  highest_ = {walls.right ? box.width + kWallSlack : kNone,
              walls.top ? box.height + kWallSlack : kNone};
}

b2Vec2 WallContainment::putBack(b2Body& ball, double mass) {
  b2Vec2 velocity = ball.GetLinearVelocity();
  b2Vec2 position = ball.GetPosition();
  const bool x =
      containAxis(position.x, velocity.x, box_.width, lowest_.x, highest_.x, mass, impulse_);
  const bool y =
      containAxis(position.y, velocity.y, box_.height, lowest_.y, highest_.y, mass, impulse_);
  if (x || y) {
    ball.SetTransform(position, 0.0f);
    ball.SetLinearVelocity(velocity);
    ++ballsPutBack_;
  }
  return velocity;
}

}  // namespace fooball::box2d_detail
