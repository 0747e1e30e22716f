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
    ++counts->wallCollisions;
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

void tagBall(btCollisionObject& object, ContactCounts* counts) {
  object.setUserIndex(kBallKind);
  object.setUserPointer(counts);
}

void tagWall(btCollisionObject& object, ContactCounts* counts) {
  object.setUserIndex(kWallKind);
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
