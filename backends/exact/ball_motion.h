#pragma once

#include <cstdint>
#include <limits>

#include "axis.h"
#include "fooball/vec2.h"

namespace fooball::exact {

/// What checking a ball as a neighbour reads, in one cache line. Position and velocity hold at
/// `time`, the ball's own clock; it is advanced only when an event involves it.
struct alignas(64) BallMotion {
  Vec2 position;              ///< m
  Vec2 velocity;              ///< m/s
  double time = 0.0;          ///< s since the step began
  double radius = 0.0;        ///< m
  std::uint64_t version = 0;  ///< bumped whenever the motion changes (lazy invalidation)
  /// s, copy of the time of the ball's interaction event (BallSchedule), which every neighbour
  /// check compares against.
  double interactionTime = std::numeric_limits<double>::infinity();
};

/// Beside the walls' sideBit() in a ball's rest bits: asleep (ball_rest.cpp), held still by
/// walls and sleeping balls, velocity 0 and no gravity felt.
inline constexpr std::uint8_t kAsleep = 1u << 4;

/// m/s², the gravity on a ball resting on the walls in `restingOn` (sideBit() per wall): the
/// walls carry its normal components.
inline Vec2 gravityOn(std::uint8_t restingOn, Vec2 gravity) {
  if ((restingOn & axisSideBits(0)) != 0) gravity.x = 0.0;
  if ((restingOn & axisSideBits(1)) != 0) gravity.y = 0.0;
  return gravity;
}

}  // namespace fooball::exact
