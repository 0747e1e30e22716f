#include "contact_counter.h"

#include <cstdint>

#include "collision_filter.h"

namespace fooball::chipmunk_detail {

namespace {

cpBool countBallCollision(cpArbiter* /*arbiter*/, cpSpace* /*space*/, cpDataPointer data) {
  ++static_cast<ContactCounts*>(data)->ballCollisions;
  return cpTrue;
}

cpBool countWallCollision(cpArbiter* arbiter, cpSpace* /*space*/, cpDataPointer data) {
  // The handler is for (ball, wall): Chipmunk hands the shapes over in that order.
  CP_ARBITER_GET_SHAPES(arbiter, ball, wall);
  auto* counts = static_cast<ContactCounts*>(data);
  const auto index = reinterpret_cast<std::uintptr_t>(cpBodyGetUserData(cpShapeGetBody(ball)));
  const auto bit =
      static_cast<common::WallBit>(reinterpret_cast<std::uintptr_t>(cpShapeGetUserData(wall)));
  counts->wallCollisions += common::touchWall(counts->touches[index], bit);
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
