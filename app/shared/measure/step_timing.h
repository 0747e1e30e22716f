#pragma once

#include <limits>
#include <optional>
#include <stop_token>

#include "fooball/backend.h"

namespace fooball::measure {

/// s of CPU time used by this process so far, all threads together.
double processCpuSeconds();

/// How one scene's step is timed: untimed warm-up steps, then timed ones.
struct StepTiming {
  double dt = 1.0 / 60.0;  ///< s per step
  /// Untimed steps first: the first one grows buffers and sorts the balls (Box2D v3's benchmark
  /// habit), and a gas started on a lattice is not yet the gas a user runs: Box2D's steps grow
  /// dearer while it thermalises (docs/performance.md), so the capacity tool warms up for a
  /// simulated second.
  int warmUpSteps = 1;
  int timedSteps = 9;
  /// ms: once the median of the warm-up steps after the first (5 or more) is over this, the
  /// scene is plainly over budget and the rest is not run (a million balls of Box2D would take
  /// minutes); that median is the result. The first steps after a load can cost several steady
  /// steps (Box2D builds its contact pairs), so the capacity tool sets this to 10× the budget.
  double giveUpAboveMs = std::numeric_limits<double>::infinity();
};

/// The median wall-clock time (ms) of `timing.timedSteps` steps, timed one by one after
/// `timing.warmUpSteps` untimed ones. The median rather than the mean, so a step that lost the
/// CPU to another process does not count. Empty when `stop` is requested (checked between
/// steps).
std::optional<double> medianStepMs(Backend& backend, const StepTiming& timing,
                                   std::stop_token stop = {});

}  // namespace fooball::measure
