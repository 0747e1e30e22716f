#pragma once

#include <box2d/b2_world_callbacks.h>

#include <cstdint>

namespace fooball::box2d_detail {

/// Counts collisions and the walls' impulse from Box2D's contact callbacks.
///
/// Counting choice: a collision is a contact that *begins* touching (BeginContact). A contact
/// that stays touching over several steps — a slow bounce whose overlap outlasts a step, balls
/// pressed together in a crowd — counts once however many impulses it exchanges, as a user
/// would count it; when it ends and the pair touches again, that is a new collision. Note that
/// with restitution 1 and threshold 0 Box2D never lets a ball rest: under gravity a "resting"
/// ball keeps hopping (each step's g·h of approach speed is reflected), and every hop that
/// breaks contact counts again. A wall is any static body (only walls are static); a wall is made
/// of several pieces (wall_bodies.h), and a ball that begins touching one while it touches
/// another piece of the same wall does not begin a new collision.
///
/// The wall impulse is the sum of the normal impulses (N·s) Box2D reports for wall contacts
/// after every solve (PostSolve), including the sub-steps of continuous collision: exactly the
/// momentum the walls give the balls, Σ|Δp|. A bounce gives 2mv; over time t a ball on the floor
/// gets m·g·t plus its own change of momentum.
///
/// Being the world's one contact listener, it also drops the contacts with the corners where
/// two wall pieces meet before each solve (PreSolve, seam_contacts.h).
class ContactCounter final : public b2ContactListener {
 public:
  void BeginContact(b2Contact* contact) override;
  void PreSolve(b2Contact* contact, const b2Manifold* oldManifold) override;
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

  void reset() {
    ballCollisions = 0;
    wallCollisions = 0;
    wallImpulse = 0.0;
  }

  std::uint64_t ballCollisions = 0;  ///< ball–ball contacts begun
  std::uint64_t wallCollisions = 0;  ///< ball–wall contacts begun
  double wallImpulse = 0.0;          ///< N·s
};

}  // namespace fooball::box2d_detail
