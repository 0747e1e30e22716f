#pragma once

#include <box2d/b2_world_callbacks.h>

#include <cstdint>
#include <span>
#include <vector>

#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::box2d_detail {

/// Counts collisions and the walls' impulse from Box2D's contact callbacks.
///
/// Counting choice: a ball–ball collision is a contact that *begins* touching (BeginContact). A
/// contact that stays touching over several steps — a slow bounce whose overlap outlasts a step,
/// balls pressed together in a crowd — counts once however many impulses it exchanges, as a user
/// would count it; when it ends and the pair touches again, that is a new collision. A ball–wall
/// contact that begins is a wall collision by the rule of common/wall_touches.h: unless the ball
/// still touches that wall. With restitution 1 and threshold 0 Box2D never lets a ball rest:
/// under gravity a "resting" ball keeps hopping (each step's g·h of approach speed is reflected),
/// and each hop breaks the contact; it is one collision until the ball leaves the wall. A wall is
/// any static body (only walls are static), its common::WallBit in its user data; a ball's body
/// holds its index. A wall is made of several pieces (wall_bodies.h): touching one piece and then
/// the next is touching the same wall.
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

  /// Forgets every count and touch, for `balls` balls whose bodies hold their index.
  void reset(std::size_t balls) {
    ballCollisions = 0;
    wallCollisions = 0;
    wallImpulse = 0.0;
    touches_.assign(balls, 0);
  }

  /// Forgets the walls each ball has left (after each Box2D step); `balls` in index order.
  void releaseWalls(std::span<b2Body* const> balls, const Box& box);

  /// Ball `index` was edited: its contacts begin anew.
  void forgetBall(std::size_t index) { touches_[index] = 0; }

  std::uint64_t ballCollisions = 0;  ///< ball–ball contacts begun
  std::uint64_t wallCollisions = 0;  ///< ball–wall contacts begun
  double wallImpulse = 0.0;          ///< N·s

 private:
  std::vector<common::WallTouches> touches_;  ///< per ball
};

}  // namespace fooball::box2d_detail
