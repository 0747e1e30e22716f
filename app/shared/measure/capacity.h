#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "capacity_search.h"
#include "fooball/run_spec.h"
#include "registry.h"
#include "step_timing.h"

namespace fooball::measure {

/// How `fooball-cli capacity` and Tools → Benchmark measure: the standard gas
/// (standardGas(N, packingFraction)), one step = one frame of `dt` with the backend's default
/// options plus `options`, the median of `timedSteps` steps once the gas has run untimed for
/// `warmUpSeconds`.
struct CapacitySettings {
  double budgetMs = 1000.0 / 60.0;  ///< ms per step: one 60 Hz frame
  double dt = 1.0 / 60.0;           ///< s
  double packingFraction = 0.2;
  /// s of simulated time before the timing starts, so every backend is timed in the steady
  /// state: the lattice start has thermalised (about 5 collisions per ball per second at
  /// φ = 0.2). 0 still steps once untimed (it grows buffers).
  double warmUpSeconds = 1.0;
  int timedSteps = 9;
  /// "KEY=VALUE", applied to every measured backend that has the option KEY, e.g. "substeps=1".
  std::vector<std::string> options;
  SearchLimits limits;
};

/// One run's capacity.
struct CapacityResult {
  std::string backend;  ///< the run spec's text: the backend's name, then its own options
  std::vector<std::string> options;  ///< those of CapacitySettings::options it took
  SearchOutcome outcome;
};

/// Where a capacity run is, for a progress bar.
struct CapacityProgress {
  std::string_view backend;      ///< the run spec's text
  std::size_t backendIndex = 0;  ///< of backendCount
  std::size_t backendCount = 0;
  SearchProgress search;  ///< within this backend
  double fraction = 0.0;  ///< of the whole run, in [0, 1)
};

/// One run per backend, at its defaults.
std::vector<RunSpec> defaultRuns(std::span<const BackendInfo> backends);

/// Throws std::invalid_argument when a setting is out of range, a run spec names an unknown
/// backend or option (or a value out of range), or an option of `settings` is unknown to every
/// measured backend (or out of range for one that has it).
void checkCapacitySettings(std::span<const RunSpec> runs, const CapacitySettings& settings);
inline void checkCapacitySettings(std::span<const BackendInfo> backends,
                                  const CapacitySettings& settings) {
  checkCapacitySettings(defaultRuns(backends), settings);
}

/// How `settings` times one ball count: the warm-up rounded up to whole steps (at least one),
/// given up at 10× the budget.
StepTiming stepTimingOf(const CapacitySettings& settings);

/// The capacity of each run in turn, on the calling thread (seconds to minutes: run it off the
/// GUI thread). A run is a backend with its own options (a run spec, e.g.
/// "chipmunk:spatial_hash=1", so one backend can be measured in several settings side by side);
/// its options are set after those of `settings`, so they win where both name a key.
/// `progress` is called after every ball count measured; a stop request ends the run within one
/// step, and the runs not finished are left out (the one cut short is reported with
/// outcome.cancelled). Each result is labelled with its run spec's text.
std::vector<CapacityResult> measureCapacity(
    std::span<const RunSpec> runs, const CapacitySettings& settings,
    const std::function<void(const CapacityProgress&)>& progress = {}, std::stop_token stop = {});

/// Every backend of `backends` at its defaults.
inline std::vector<CapacityResult> measureCapacity(
    std::span<const BackendInfo> backends, const CapacitySettings& settings,
    const std::function<void(const CapacityProgress&)>& progress = {}, std::stop_token stop = {}) {
  return measureCapacity(defaultRuns(backends), settings, progress, std::move(stop));
}

/// What a reader must know beside a result, "" if nothing: what a backend that is not native
/// code runs as (BackendInfo::runtime, e.g. "WebAssembly in Node.js"), and a search that ended
/// early, e.g. "time limit: best count so far". The CLI's table and Tools → Benchmark show it.
std::string capacityNote(const CapacityResult& result);

/// The `capacity --csv` header, as DESIGN.md states it.
inline constexpr std::string_view kCapacityCsvHeader = "backend,balls,median_step_ms";

/// kCapacityCsvHeader, then one row per result.
void writeCapacityCsv(std::ostream& out, std::span<const CapacityResult> results);

}  // namespace fooball::measure
