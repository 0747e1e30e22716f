#include "wall_containment.h"

namespace fooball::chipmunk_detail {

WallContainment::WallContainment(const Box& box, const Walls& walls, Vec2 gravity, double thickness)
    : box_(box), mirror_(box, walls, gravity), thickness_(thickness) {}

void WallContainment::bringBack(cpBody* ball, double radius, double mass,
                                common::WallTouches& touches) {
  const cpVect position = cpBodyGetPosition(ball);
  const cpVect velocity = cpBodyGetVelocity(ball);
  Vec2 p{position.x, position.y};
  Vec2 v{velocity.x, velocity.y};
  const common::WallMirror::Return brought = mirror_.bringBack(p, v);
  cpBodySetPosition(ball, cpv(p.x, p.y));
  cpBodySetVelocity(ball, cpv(v.x, v.y));
  ++ballsBroughtBack_;
  const double unseen = radius + 2.0 * thickness_;  // m
  for (const common::WallMirror::AxisReturn& axis : {brought.x, brought.y}) {
    if (!axis.brought) continue;
    impulse_ += mass * axis.impulse;
    if (axis.depth > unseen) wallCollisions_ += common::touchWall(touches, axis.wall);
  }
}

}  // namespace fooball::chipmunk_detail
