#include "capacity_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fooball::measure {

namespace {

/// Bisections still needed to narrow [within, beyond] to the resolution.
double bisectionsLeft(std::size_t within, std::size_t beyond, double resolution) {
  const double width = static_cast<double>(beyond - within);
  const double target = std::max(1.0, resolution * static_cast<double>(within));
  return width > target ? std::ceil(std::log2(width / target)) : 0.0;
}

class Search {
 public:
  Search(const CostOf& cost, double budget, const SearchLimits& limits,
         const std::function<void(const SearchProgress&)>& progress,
         const std::function<double()>& secondsElapsed)
      : cost_(cost),
        budget_(budget),
        limits_(limits),
        progress_(progress),
        secondsElapsed_(secondsElapsed) {}

  SearchOutcome run() {
    std::size_t count = std::clamp<std::size_t>(limits_.firstBalls, 1, limits_.maxBalls);
    // Up by doubling while within the budget.
    for (;;) {
      const std::optional<bool> fits = measure(count);
      if (!fits) return finish();
      if (!*fits) break;
      if (count == limits_.maxBalls) {
        outcome_.reachedMaxBalls = true;
        return finish();
      }
      count = std::min(2 * count, limits_.maxBalls);
    }
    // Down by halving while nothing fitted yet.
    while (!within_ && count > 1) {
      count /= 2;
      if (!measure(count)) return finish();
    }
    // Bisect between the largest count within and the smallest beyond.
    while (within_ && beyond_ && bisectionsLeft(*within_, *beyond_, limits_.resolution) > 0) {
      if (!measure(*within_ + (*beyond_ - *within_) / 2)) break;
    }
    return finish();
  }

 private:
  /// Measures `count`: whether it is within the budget, or empty when the search must stop
  /// (cancelled or out of time).
  std::optional<bool> measure(std::size_t count) {
    if (secondsElapsed_() > limits_.timeLimitSeconds) {
      outcome_.timedOut = true;
      return std::nullopt;
    }
    const std::optional<double> measured = cost_(count);
    if (!measured) {
      outcome_.cancelled = true;
      return std::nullopt;
    }
    const Probe probe{count, *measured};
    outcome_.probes.push_back(probe);
    const bool fits = probe.medianStepMs <= budget_;
    if (fits && (!within_ || count > *within_)) {
      within_ = count;
      outcome_.balls = count;
      outcome_.medianStepMs = probe.medianStepMs;
    } else if (!fits && (!beyond_ || count < *beyond_)) {
      beyond_ = count;
    }
    report(probe);
    return fits;
  }

  void report(const Probe& probe) {
    if (!progress_) return;
    // Probes left: doubling up to the cap (none once a count is over), then the bisection.
    double left = std::ceil(std::log2(1.0 / limits_.resolution));
    if (within_ && beyond_) {
      left = bisectionsLeft(*within_, *beyond_, limits_.resolution);
    } else if (!beyond_) {
      left += std::log2(static_cast<double>(limits_.maxBalls) / static_cast<double>(probe.balls));
    }
    const auto done = static_cast<double>(outcome_.probes.size());
    progress_({probe, done / (done + left + 1.0)});
  }

  SearchOutcome finish() { return std::move(outcome_); }

  const CostOf& cost_;
  double budget_;
  SearchLimits limits_;
  const std::function<void(const SearchProgress&)>& progress_;
  const std::function<double()>& secondsElapsed_;
  std::optional<std::size_t> within_;  ///< the largest count within the budget so far
  std::optional<std::size_t> beyond_;  ///< the smallest count over the budget so far
  SearchOutcome outcome_;
};

}  // namespace

SearchOutcome searchCapacity(const CostOf& cost, double budget, const SearchLimits& limits,
                             const std::function<void(const SearchProgress&)>& progress,
                             const std::function<double()>& secondsElapsed) {
  std::function<double()> clock = secondsElapsed;
  if (!clock) {
    const auto start = std::chrono::steady_clock::now();
    clock = [start] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
  }
  return Search(cost, budget, limits, progress, clock).run();
}

}  // namespace fooball::measure
