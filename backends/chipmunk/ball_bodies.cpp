#include "ball_bodies.h"

#include <chipmunk/chipmunk_unsafe.h>

#include <cmath>

#include "collision_filter.h"
#include "elastic_material.h"

namespace fooball::chipmunk_detail {

BallBody createBall(Space& space, const BallDef& ball, bool ballCollisions) {
  cpBody* body = space.add(cpBodyNew(ball.mass, INFINITY));
  cpBodySetPosition(body, cpv(ball.position.x, ball.position.y));
  cpBodySetVelocity(body, cpv(ball.velocity.x, ball.velocity.y));
  cpShape* shape = space.add(cpCircleShapeNew(body, ball.radius, cpvzero));
  makeElastic(shape);
  cpShapeSetCollisionType(shape, kBallType);
  cpShapeSetFilter(shape, ballFilter(ballCollisions));
  return {body, shape};
}

void setBallShape(Space& space, const BallBody& ball, double radius, double mass) {
  cpBodySetMass(ball.body, mass);
  if (cpCircleShapeGetRadius(ball.shape) != radius) {
    cpCircleShapeSetRadius(ball.shape, radius);
    cpSpaceReindexShape(space.get(), ball.shape);
  }
}

void setBallCollisions(const BallBody& ball, bool ballCollisions) {
  cpShapeSetFilter(ball.shape, ballFilter(ballCollisions));
}

}  // namespace fooball::chipmunk_detail
