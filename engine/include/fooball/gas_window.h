#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

#include "fooball/scene.h"

namespace fooball {

/// Rates of a run's cumulative counters over the last few seconds of simulated time: the wall
/// pressure (from the impulse the walls deliver) and the ball–ball collision rate, to compare
/// with the hard-disk theory. Fed one sample at a time (a run's time and counters), in time
/// order; a sample older than the last is taken as a restart and clears the window.
class GasWindow {
 public:
  /// `seconds` > 0: how much simulated time the rates average over (s).
  explicit GasWindow(double seconds = 2.0);

  void add(double time, double wallImpulse, std::uint64_t ballCollisions);
  void clear() { samples_.clear(); }

  /// s between the oldest and the newest sample kept; the rates need > 0.
  double span() const;
  /// N/m: wall impulse per second per metre of wall that is on (2D pressure), over span().
  /// 0 with no span or no wall on. Walls are taken as the box's full sides.
  double wallPressure(const Box& box, const Walls& walls) const;
  /// Ball–ball collisions per ball per second over span() (each collision involves two balls).
  double collisionRate(std::size_t balls) const;

 private:
  struct Sample {
    double time;         ///< s
    double wallImpulse;  ///< N·s, cumulative
    std::uint64_t ballCollisions;
  };
  double seconds_;
  std::deque<Sample> samples_;
};

}  // namespace fooball
