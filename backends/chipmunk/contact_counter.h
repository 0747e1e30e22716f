#pragma once

#include <chipmunk/chipmunk.h>

#include <cstdint>

namespace fooball::chipmunk_detail {

/// Collisions and the walls' impulse, counted by Chipmunk's collision handlers.
///
/// Counting choice (as the Box2D adapter's): a collision is a contact that *begins* (the begin
/// callback, called when an arbiter is new or comes back from the cache after the shapes stopped
/// touching). A contact that stays touching over several steps counts once however many impulses
/// it exchanges. Under gravity a ball "resting" with elasticity 1 keeps hopping (each step's
/// g·h of approach speed is reflected), and every hop that breaks contact counts again. Each wall
/// is one segment (wall_segments.h), so there are no seams between pieces to discount.
///
/// The wall impulse is |cpArbiterTotalImpulse| of every ball–wall arbiter after each solve
/// (postSolve): the accumulated impulse of the step, warm start included, which is exactly the
/// momentum the wall gave the ball, Σ|Δp|. The wall containment (wall_containment.h) adds the
/// bounces it makes itself.
struct ContactCounts {
  std::uint64_t ballCollisions = 0;  ///< ball–ball contacts begun
  std::uint64_t wallCollisions = 0;  ///< ball–wall contacts begun
  double wallImpulse = 0.0;          ///< N·s
};

/// Installs the handlers for ball–ball and ball–wall pairs (collision_filter.h's types), counting
/// into `counts`, which must outlive the space.
void installContactCounter(cpSpace* space, ContactCounts* counts);

}  // namespace fooball::chipmunk_detail
