#pragma once

#include <chipmunk/chipmunk.h>

#include <cstdint>
#include <vector>

#include "common/wall_touches.h"

namespace fooball::chipmunk_detail {

/// Collisions and the walls' impulse, counted by Chipmunk's collision handlers.
///
/// Counting choice (as the Box2D adapter's): a ball–ball collision is a contact that *begins* (the
/// begin callback, called when an arbiter is new or comes back from the cache after the shapes
/// stopped touching). A contact that stays touching over several steps counts once however many
/// impulses it exchanges. A ball–wall contact that begins is a wall collision by the rule of
/// common/wall_touches.h, unless the ball still touches that wall: under gravity a ball "resting"
/// with elasticity 1 keeps hopping (each step's g·h of approach speed is reflected), and each hop
/// breaks the contact; it is one collision until the ball leaves the wall. A ball's body holds its
/// index as user data, a wall's segment its common::WallBit (wall_segments.h).
///
/// The wall impulse is |cpArbiterTotalImpulse| of every ball–wall arbiter after each solve
/// (postSolve): the accumulated impulse of the step, warm start included, which is exactly the
/// momentum the wall gave the ball, Σ|Δp|. The wall containment (wall_containment.h) adds the
/// bounces it makes itself.
struct ContactCounts {
  std::uint64_t ballCollisions = 0;  ///< ball–ball contacts begun
  std::uint64_t wallCollisions = 0;  ///< ball–wall contacts begun
  double wallImpulse = 0.0;          ///< N·s
  /// Per ball, the walls it touches; released after each Chipmunk step (chipmunk_stepping.cpp).
  std::vector<common::WallTouches> touches;
};

/// Installs the handlers for ball–ball and ball–wall pairs (collision_filter.h's types), counting
/// into `counts`, which must outlive the space.
void installContactCounter(cpSpace* space, ContactCounts* counts);

}  // namespace fooball::chipmunk_detail
