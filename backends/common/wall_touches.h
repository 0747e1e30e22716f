#pragma once

#include <cstdint>

#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball::common {

/// The rule every backend counts wall collisions by (`wall_collisions`, DESIGN.md's metrics). A
/// wall collision is one reversal of a ball's approach to a wall: the wall turns it back or stops
/// it. A ball the wall acts on again while it still touches that wall — held on the floor by
/// gravity or by the balls above, and clamped or turned back in every substep — is in the same
/// collision, not in a new one each substep. A ball touches a wall from the moment the wall acts
/// on it until its gap to the wall grows beyond kWallReleaseFraction of its radius.
///
/// Each ball keeps one byte, WallTouches, with a bit per wall it touches; the solvers keep it
/// beside the ball (by slot or by scene index) and call these two functions.
using WallTouches = std::uint8_t;

enum WallBit : WallTouches { kLeftWall = 1, kRightWall = 2, kBottomWall = 4, kTopWall = 8 };

/// How far a ball must leave a wall (its gap, as a fraction of its radius) before the wall's next
/// action on it is a new collision. A resting ball's gap never gets there: a time-stepped solver
/// lifts it by g·h² per substep at most (1.7e-4 m at h = 1/240 s, 2% of the 8.8 mm balls the
/// default preset gets at 10,000 balls), and a pile's jitter stays within the overlap its solver
/// leaves (a few % of r). A real bounce leaves by far more: a gas ball crosses the box, and a
/// ball bouncing under gravity rises v²/2g.
inline constexpr double kWallReleaseFraction = 0.1;

/// The wall `wall` acted on the ball that `touches` belongs to: 1 when that begins a collision,
/// 0 when the ball already touched that wall.
inline std::uint64_t touchWall(WallTouches& touches, WallBit wall) {
  const bool already = (touches & wall) != 0;
  touches = static_cast<WallTouches>(touches | wall);
  return already ? 0 : 1;
}

/// `touches` without the walls the ball with centre `centre` (m) and radius `radius` (m) has
/// left, in the box `box` ([0, width] × [0, height]).
inline WallTouches stillTouching(WallTouches touches, Vec2 centre, double radius, const Box& box) {
  const double release = (1.0 + kWallReleaseFraction) * radius;  // m, centre to wall
  WallTouches kept = touches;
  if (centre.x > release) kept &= static_cast<WallTouches>(~kLeftWall);
  if (centre.x < box.width - release) kept &= static_cast<WallTouches>(~kRightWall);
  if (centre.y > release) kept &= static_cast<WallTouches>(~kBottomWall);
  if (centre.y < box.height - release) kept &= static_cast<WallTouches>(~kTopWall);
  return kept;
}

}  // namespace fooball::common
