#include "contact_counter.h"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace fooball::bullet_detail {

namespace {

/// btCollisionObject user indices.
constexpr int kBallKind = 1;
constexpr int kWallKind = 2;

bool isWall(const btCollisionObject& object) {
  return object.getUserIndex() == kWallKind;
}

void countStartedContact(btPersistentManifold* const& manifold) {
  const btCollisionObject& first = *manifold->getBody0();
  const btCollisionObject& second = *manifold->getBody1();
  auto* counts = static_cast<ContactCounts*>(first.getUserPointer());
  if (counts == nullptr) return;  // not one of ours
  if (isWall(first) || isWall(second)) {
    const btCollisionObject& wall = isWall(first) ? first : second;
    const btCollisionObject& ball = isWall(first) ? second : first;
    const auto bit = static_cast<common::WallBit>(wall.getUserIndex2());
    counts->wallCollisions += common::touchWall(counts->touches[ball.getUserIndex2()], bit);
  } else {
    ++counts->ballCollisions;
  }
}

bool setCallback() {
  gContactStartedCallback = countStartedContact;
  return true;
}

}  // namespace

void installContactCounter() {
  static const bool installed = setCallback();
  (void)installed;
}

void tagBall(btCollisionObject& object, ContactCounts* counts, std::size_t index) {
  object.setUserIndex(kBallKind);
  object.setUserIndex2(static_cast<int>(index));
  object.setUserPointer(counts);
}

void tagWall(btCollisionObject& object, ContactCounts* counts, common::WallBit wall) {
  object.setUserIndex(kWallKind);
  object.setUserIndex2(wall);
  object.setUserPointer(counts);
}

void addWallImpulse(btDispatcher& dispatcher, ContactCounts& counts) {
  const int manifolds = dispatcher.getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    if (!isWall(*manifold.getBody0()) && !isWall(*manifold.getBody1())) continue;
    for (int point = 0; point < manifold.getNumContacts(); ++point)
      counts.wallImpulse +=
          static_cast<double>(manifold.getContactPoint(point).getAppliedImpulse());
  }
}

}  // namespace fooball::bullet_detail
