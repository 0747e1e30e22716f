#include "wall_containment.h"

#include <cmath>

namespace fooball::box2d_detail {

namespace {

/// One axis of one ball against the walls at 0 and `side` (m), each on or off. Returns whether
/// the ball was put back, and adds the impulse the wall gave to `impulse`.
bool containAxis(float& position, float& velocity, double side, bool lowOn, bool highOn,
                 double mass, double& impulse) {
  const double p = static_cast<double>(position);
  double face;
  bool outward;
  if (lowOn && p < -kWallSlack) {
    face = 0.0;
    outward = velocity < 0.0f;
  } else if (highOn && p > side + kWallSlack) {
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

Containment containBalls(std::span<b2Body* const> balls, std::span<const double> masses,
                         const Box& box, const Walls& walls) {
  Containment done;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    b2Body& ball = *balls[i];
    b2Vec2 position = ball.GetPosition();
    b2Vec2 velocity = ball.GetLinearVelocity();
    const bool x = containAxis(position.x, velocity.x, box.width, walls.left, walls.right,
                               masses[i], done.impulse);
    const bool y = containAxis(position.y, velocity.y, box.height, walls.bottom, walls.top,
                               masses[i], done.impulse);
    if (!x && !y) continue;
    ball.SetTransform(position, 0.0f);
    ball.SetLinearVelocity(velocity);
    ++done.ballsPutBack;
  }
  return done;
}

}  // namespace fooball::box2d_detail
