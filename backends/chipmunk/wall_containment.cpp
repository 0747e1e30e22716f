#include "wall_containment.h"

#include <utility>

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
  // Brought back inside, the ball lies in the half of the box next to the wall it crossed.
  const common::WallBit xWall = p.x < 0.5 * box_.width ? common::kLeftWall : common::kRightWall;
  const common::WallBit yWall = p.y < 0.5 * box_.height ? common::kBottomWall : common::kTopWall;
  for (const auto& [axis, wall] : {std::pair{brought.x, xWall}, std::pair{brought.y, yWall}}) {
    if (!axis.brought) continue;
    impulse_ += mass * axis.impulse;
    if (axis.depth > unseen) wallCollisions_ += common::touchWall(touches, wall);
  }
}

}  // namespace fooball::chipmunk_detail
