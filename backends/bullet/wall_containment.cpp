#include "wall_containment.h"

#include <utility>

#include "plane_vectors.h"

namespace fooball::bullet_detail {

WallContainment::WallContainment(const Box& box, const Walls& walls, Vec2 gravity)
    : box_(box), mirror_(box, walls, gravity) {}

void WallContainment::bringBack(btRigidBody& ball, double mass, common::WallTouches& touches) {
  Vec2 p = fromBullet(ball.getWorldTransform().getOrigin());
  Vec2 v = fromBullet(ball.getLinearVelocity());
  const common::WallMirror::Return brought = mirror_.bringBack(p, v);
  btTransform transform = ball.getWorldTransform();
  transform.setOrigin(toBullet(p));
  ball.setWorldTransform(transform);
  ball.setLinearVelocity(toBullet(v));
  ++ballsBroughtBack_;
  // Brought back inside, the ball lies in the half of the box next to the wall it crossed.
  const common::WallBit xWall = p.x < 0.5 * box_.width ? common::kLeftWall : common::kRightWall;
  const common::WallBit yWall = p.y < 0.5 * box_.height ? common::kBottomWall : common::kTopWall;
  for (const auto& [axis, wall] : {std::pair{brought.x, xWall}, std::pair{brought.y, yWall}}) {
    impulse_ += mass * axis.impulse;
    if (axis.leaving) wallCollisions_ += common::touchWall(touches, wall);
  }
}

}  // namespace fooball::bullet_detail
