#include "wall_containment.h"

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
  for (const common::WallMirror::AxisReturn& axis : {brought.x, brought.y}) {
    impulse_ += mass * axis.impulse;
    if (axis.leaving) wallCollisions_ += common::touchWall(touches, axis.wall);
  }
}

}  // namespace fooball::bullet_detail
