#pragma once

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>

#include <cstdint>
#include <vector>

#include "common/wall_touches.h"

namespace fooball::bullet_detail {

/// Collisions and the walls' impulse, counted from Bullet's persistent manifolds.
///
/// Counting choice (as the Box2D and Chipmunk adapters'): a ball–ball collision is a contact that
/// *begins*: a pair's manifold gaining its first point (gContactStartedCallback, called by
/// btPersistentManifold::addManifoldPoint when the manifold had none). A contact that stays over
/// several steps counts once however many impulses it exchanges; it ends when its last point is
/// dropped, once the pair is farther apart than the breaking threshold (contact_processing.h) or
/// its bounding boxes part, and the next touch is a new collision. A ball–wall contact that
/// begins is a wall collision by the rule of common/wall_touches.h: unless the ball still touches
/// that wall (a resting ball whose contact breaks and begins again). A ball's second user index
/// is its index, a wall's its common::WallBit. A ball–ball point is made only
/// for overlapping spheres; a ball–wall point already within the breaking threshold of the plane.
///
/// Bullet's callback is a process-wide function pointer, not a per-world listener. It is set once
/// (installContactCounter) to a function that finds the counts through the objects' user pointer
/// (tagBall, tagWall): each adapter counts its own world's contacts, and worlds stepped on other
/// threads touch only their own counts.
///
/// The wall impulse is the sum of the normal impulses the solver applied at wall contact points
/// (btManifoldPoint::getAppliedImpulse), read after every Bullet step (addWallImpulse): the warm
/// start included, and without the split impulse's push, which moves positions only. Friction is
/// 0, so that is exactly the momentum the walls gave the balls, Σ|Δp|.
struct ContactCounts {
  std::uint64_t ballCollisions = 0;  ///< ball–ball contacts begun
  std::uint64_t wallCollisions = 0;  ///< ball–wall contacts begun
  double wallImpulse = 0.0;          ///< N·s
  /// Per ball, the walls it touches; released after each Bullet step (wall_containment.h).
  std::vector<common::WallTouches> touches;
};

/// Points Bullet's contact-started callback at the counting function; once per process, safe to
/// call from any thread.
void installContactCounter();

/// Marks `object` as ball `index` or as the wall `wall`, whose contacts count into `counts` (which
/// must outlive it).
void tagBall(btCollisionObject& object, ContactCounts* counts, std::size_t index);
void tagWall(btCollisionObject& object, ContactCounts* counts, common::WallBit wall);

/// Adds the normal impulses of every ball–wall contact point of the last Bullet step to
/// counts->wallImpulse.
void addWallImpulse(btDispatcher& dispatcher, ContactCounts& counts);

}  // namespace fooball::bullet_detail
