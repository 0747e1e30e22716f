#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "fooball/scene.h"

namespace fooball::measure {

/// Where the capacity search looks and when it gives up.
struct SearchLimits {
  std::size_t firstBalls = 1000;     ///< the first count measured
  std::size_t maxBalls = kMaxBalls;  ///< never more: the scene format's limit (2'000'000)
  /// The bisection stops when the counts within and beyond the budget are this close, relative
  /// to the count within. 2%: finer than the run-to-run noise of a median step.
  double resolution = 0.02;
  double timeLimitSeconds = 120.0;  ///< per backend; the best count so far is kept
};

/// One ball count measured.
struct Probe {
  std::size_t balls = 0;
  double medianStepMs = 0.0;
};

struct SearchOutcome {
  /// The largest count measured within the budget; 0 when even one ball is over it.
  std::size_t balls = 0;
  double medianStepMs = 0.0;  ///< of that count
  bool reachedMaxBalls = false;
  bool timedOut = false;
  bool cancelled = false;
  std::vector<Probe> probes;  ///< every count measured, in order
};

/// What a search has done so far, for a progress bar.
struct SearchProgress {
  Probe latest;
  double fraction = 0.0;  ///< an estimate in [0, 1)
};

/// The cost of `balls` balls, e.g. a median step in ms; empty to cancel the search.
using CostOf = std::function<std::optional<double>(std::size_t balls)>;

/// The largest ball count whose cost stays within `budget`, assuming cost grows with the count:
/// doubling from limits.firstBalls until a count is over the budget (or halving, if the first
/// one already is), then bisecting between the last count within and the first beyond until
/// they are limits.resolution apart. `secondsElapsed` is the clock for the time limit.
SearchOutcome searchCapacity(const CostOf& cost, double budget, const SearchLimits& limits,
                             const std::function<void(const SearchProgress&)>& progress = {},
                             const std::function<double()>& secondsElapsed = {});

}  // namespace fooball::measure
