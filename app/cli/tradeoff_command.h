#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace fooball::cli {

inline constexpr const char* kTradeoffPreset = "gas";

/// Everything `fooball-cli tradeoff` was asked to do, as parsed.
struct TradeoffOptions {
  std::optional<std::filesystem::path> scenePath;  ///< --scene; the preset when absent
  std::string presetName = kTradeoffPreset;
  std::vector<std::string> backends;  ///< --backend, repeatable; empty: every registered one
  double duration = 2.0;              ///< --duration, s
  double compareAt = 0.2;             ///< --compare-at, s
  std::optional<std::filesystem::path> csvPath;
  std::optional<std::filesystem::path> chartPath;
  bool quiet = false;
};

/// `fooball-cli tradeoff`: every backend over a grid of its settings on one scene, CPU cost per
/// simulated second against energy, momentum, overlap and trajectory errors (the exact backend
/// is the reference), printed with each backend's Pareto front, written as CSV and drawn as a
/// PNG chart when asked. Bad input throws UsageError, SceneError or std::invalid_argument.
void tradeoffCommand(const TradeoffOptions& options, std::ostream& out);

}  // namespace fooball::cli
