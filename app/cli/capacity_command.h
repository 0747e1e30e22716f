#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace fooball::cli {

/// Everything `fooball-cli capacity` was asked to do, as parsed.
struct CapacityOptions {
  std::vector<std::string>
      backends;  ///< --backend run specs, repeatable; empty: every registered one
  double budgetMs = 1000.0 / 60.0;       ///< --budget-ms
  double packingFraction = 0.2;          ///< --packing-fraction
  double warmUpSeconds = 1.0;            ///< --warm-up: simulated s untimed before timing
  int steps = 9;                         ///< --steps: timed steps per ball count, median taken
  double timeLimitSeconds = 120.0;       ///< --time-limit, per backend
  std::vector<std::string> assignments;  ///< --option KEY=VALUE, for every backend that has KEY
  std::optional<std::filesystem::path> csvPath;
  std::optional<std::filesystem::path> chartPath;
  bool quiet = false;
};

/// `fooball-cli capacity`: for each backend, the largest standard-gas ball count whose median
/// step fits the budget (measure::measureCapacity), printed as a table, written as CSV and
/// drawn as a PNG chart when asked. Bad input throws UsageError or std::invalid_argument.
void capacityCommand(const CapacityOptions& options, std::ostream& out);

}  // namespace fooball::cli
