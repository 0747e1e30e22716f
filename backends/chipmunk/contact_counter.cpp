#include "contact_counter.h"

#include "collision_filter.h"

namespace fooball::chipmunk_detail {

namespace {

cpBool countBallCollision(cpArbiter* /*arbiter*/, cpSpace* /*space*/, cpDataPointer data) {
  ++static_cast<ContactCounts*>(data)->ballCollisions;
  return cpTrue;
}

cpBool countWallCollision(cpArbiter* /*arbiter*/, cpSpace* /*space*/, cpDataPointer data) {
  ++static_cast<ContactCounts*>(data)->wallCollisions;
  return cpTrue;
}

void addWallImpulse(cpArbiter* arbiter, cpSpace* /*space*/, cpDataPointer data) {
  static_cast<ContactCounts*>(data)->wallImpulse += cpvlength(cpArbiterTotalImpulse(arbiter));
}

}  // namespace

void installContactCounter(cpSpace* space, ContactCounts* counts) {
  cpCollisionHandler* balls = cpSpaceAddCollisionHandler(space, kBallType, kBallType);
  balls->beginFunc = countBallCollision;
  balls->userData = counts;
  cpCollisionHandler* walls = cpSpaceAddCollisionHandler(space, kBallType, kWallType);
  walls->beginFunc = countWallCollision;
  walls->postSolveFunc = addWallImpulse;
  walls->userData = counts;
}

}  // namespace fooball::chipmunk_detail
