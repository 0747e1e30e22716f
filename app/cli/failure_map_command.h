#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace fooball::cli {

/// Everything `fooball-cli failure-map` was asked to do, as parsed.
struct FailureMapOptions {
  std::vector<std::string> backends;  ///< --backend, repeatable; empty: every registered one
  std::vector<std::string> sweeps;    ///< --sweep, repeatable; empty: all six
  std::optional<std::filesystem::path> csvPath;
  std::optional<std::filesystem::path> chartDir;  ///< PNGs go here as failure-<sweep>.png
  bool quick = false;                             ///< coarser grids, shorter scenes
  bool quiet = false;
};

/// `fooball-cli failure-map`: runs the failure-map sweeps (docs/accuracy.md) on every chosen
/// backend, prints where each one starts to fail, writes every point as CSV and draws one PNG
/// per sweep when asked. Bad input throws UsageError or std::invalid_argument.
void failureMapCommand(const FailureMapOptions& options, std::ostream& out);

}  // namespace fooball::cli
