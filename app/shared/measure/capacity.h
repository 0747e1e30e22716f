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
#include "registry.h"

namespace fooball::measure {

/// How `fooball-cli capacity` and Tools → Benchmark measure: the standard gas
/// (standardGas(N, packingFraction)), one step = one frame of `dt` with the backend's default
/// options plus `options`, the median of `timedSteps` steps after one untimed step.
struct CapacitySettings {
  double budgetMs = 1000.0 / 60.0;  ///< ms per step: one 60 Hz frame
  double dt = 1.0 / 60.0;           ///< s
  double packingFraction = 0.2;
  int timedSteps = 9;
  /// "KEY=VALUE", applied to every measured backend that has the option KEY, e.g. "substeps=1".
  std::vector<std::string> options;
  SearchLimits limits;
};

/// One backend's capacity.
struct CapacityResult {
  std::string backend;
  std::vector<std::string> options;  ///< those of CapacitySettings::options it took
  SearchOutcome outcome;
};

/// Where a capacity run is, for a progress bar.
struct CapacityProgress {
  std::string_view backend;
  std::size_t backendIndex = 0;  ///< of backendCount
  std::size_t backendCount = 0;
  SearchProgress search;  ///< within this backend
  double fraction = 0.0;  ///< of the whole run, in [0, 1)
};

/// Throws std::invalid_argument when a setting is out of range or an option of `settings` is
/// unknown to every backend of `backends` (or out of range for one that has it).
void checkCapacitySettings(std::span<const BackendInfo> backends, const CapacitySettings& settings);

/// The capacity of each backend in turn, on the calling thread (seconds to minutes: run it
/// off the GUI thread). `progress` is called after every ball count measured; a stop request
/// ends the run within one step, and the backends not finished are left out (the one cut
/// short is reported with outcome.cancelled).
std::vector<CapacityResult> measureCapacity(
    std::span<const BackendInfo> backends, const CapacitySettings& settings,
    const std::function<void(const CapacityProgress&)>& progress = {}, std::stop_token stop = {});

/// The `capacity --csv` header, as DESIGN.md states it.
inline constexpr std::string_view kCapacityCsvHeader = "backend,balls,median_step_ms";

/// kCapacityCsvHeader, then one row per result.
void writeCapacityCsv(std::ostream& out, std::span<const CapacityResult> results);

}  // namespace fooball::measure
