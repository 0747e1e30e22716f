#pragma once

#include <cstdint>
#include <vector>

#include "fooball/scene.h"
#include "particles.h"

namespace fooball::xpbd {

/// The four walls, in the order of their bits in common::WallTouches.
enum class Wall : std::uint8_t { Left, Right, Bottom, Top };

/// A wall a ball was pushed out of in this substep.
struct WallContact {
  std::uint32_t slot;
  Wall wall;
  double before;        ///< m/s, the ball's velocity into the wall before the solve (v̄_n)
  double pushed;        ///< m, how far the wall has pushed the ball back in this substep
  double change = 0.0;  ///< m/s, what the velocity passes changed v_n by (< 0: outwards)
};

/// The ball–wall non-penetration constraints (compliance 0, walls of infinite mass): each wall
/// that is on is a half-plane the centre may not pass by less than the radius. Walls that are
/// off cost nothing. Every ball is checked in every iteration, after the pairs, so the last
/// thing a substep does to positions is to put every ball inside the walls that are on: a
/// closed box keeps every ball whatever the pairs ask (a ball wider than the box sits at its
/// middle).
///
/// Contact events by the rule of common/wall_touches.h (Particles::touches): a wall contact
/// begins an event (a bounce) unless the ball still touches that wall: a ball resting on the
/// floor, pressed in every other substep, is one contact, not a bounce per substep.
class WallContacts {
 public:
  WallContacts(const Box& box, const Walls& walls) : box_(box), walls_(walls) {}

  /// Forgets the walls each ball has left (before the substep moves them).
  void release(Particles& particles) const;

  /// One pass: every ball pushed back inside the walls that are on; the contacts of this
  /// substep are added to `contacts` (first time) or accumulate their push. Returns the events
  /// begun.
  std::uint64_t project(Particles& particles, std::vector<WallContact>& contacts,
                        std::vector<std::uint32_t>& recordOf) const;

  bool anyOn() const { return walls_.left || walls_.right || walls_.bottom || walls_.top; }

 private:
  Box box_;
  Walls walls_;
};

/// One velocity pass of the walls (Müller 2020 §3.6, e = 1) over `contacts`, after the pairs':
/// with v_n the velocity into the wall, sets v_n to min(−v̄_n, 0).
void restituteWalls(Particles& particles, std::vector<WallContact>& contacts);

/// N·s: the momentum the walls gave their balls in the substep, Σ m·|Δv_n − pushed/h|: the push
/// out (which the derived velocity carries as pushed/h) and the velocity passes together. A
/// bounce at speed u gives 2mu; a ball resting on the floor m·g per second.
double wallImpulse(const Particles& particles, const std::vector<WallContact>& contacts, double h);

}  // namespace fooball::xpbd
