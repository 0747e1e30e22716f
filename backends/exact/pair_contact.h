#pragma once

#include <cmath>
#include <limits>

#include "fooball/vec2.h"

namespace fooball::exact {

/// The motion of ball j relative to ball i from now on (free_flight.h):
///   r(τ) = separation + relativeVelocity·s(τ) + relativeGravity·q(τ).
/// relativeGravity is zero unless one of the two rests on a wall, where the wall carries
/// gravity's normal component for it.
struct PairMotion {
  Vec2 separation;        ///< m, centre of j minus centre of i
  Vec2 relativeVelocity;  ///< m/s, velocity of j minus velocity of i
  Vec2 relativeGravity;   ///< m/s², effective gravity of j minus that of i
  double reach = 0.0;     ///< m, sum of the radii: the centre distance at contact
};

/// For the same gravity on both (relativeGravity = 0): the smallest s ≥ 0 at which
/// |separation + relativeVelocity·s| = reach while the balls approach, or +∞. With
/// b = r·u < 0 (approaching), c = |r|² − R² and the discriminant b² − |u|²c, the root is
/// c / (−b + √disc), the form without cancellation. A pair that rounding left touching or
/// overlapping (c ≤ 0) collides now if it approaches and never while it recedes, so a pair that
/// just bounced is not hit again.
inline double linearContactParameter(Vec2 separation, Vec2 relativeVelocity, double reach) {
  const double approach = dot(separation, relativeVelocity);
  if (approach >= 0.0) return std::numeric_limits<double>::infinity();
  const double gap = dot(separation, separation) - reach * reach;
  if (gap <= 0.0) return 0.0;
  const double discriminant = approach * approach - dot(relativeVelocity, relativeVelocity) * gap;
  if (discriminant <= 0.0) return std::numeric_limits<double>::infinity();
  return gap / (-approach + std::sqrt(discriminant));
}

enum class PairContactKind {
  None,     ///< no contact before the horizon
  Contact,  ///< contact at `time`
  Recheck,  ///< no contact before `time`; search again from there
};

struct PairContact {
  PairContactKind kind = PairContactKind::None;
  double time = 0.0;  ///< s from now
};

/// For differing gravity (a ball resting on a wall meets a flying one): the first contact within
/// `horizon` seconds (may be +∞). The relative path is curved, so the contact is found by steps
/// that can never pass it: F(τ) = |r|² − R² lies above F + F'·Δ − ½·M·Δ², where M bounds |F''|
/// over a window, so the first root of that parabola is a safe step. Far away this is a
/// conservative advance; near a contact it converges quadratically from the safe side.
PairContact acceleratedPairContact(const PairMotion& motion, double drag, double horizon);

}  // namespace fooball::exact
