#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fooball/presets.h"

namespace fooball::cli {

/// Everything `fooball-cli compare` was asked to do, as parsed; checked by compareCommand.
struct CompareOptions {
  std::optional<std::filesystem::path> scenePath;  ///< --scene; the preset when absent
  std::string presetName{kDefaultPreset};
  std::vector<std::string> runs;  ///< --run SPEC, in order: run 0 (the reference) first
  double duration = 5.0;          ///< s of simulated time
  std::optional<double> dt;       ///< s; the run group's default when absent
  std::int64_t every = 1;         ///< steps between CSV rows
  bool baseline = false;          ///< --baseline: add the chaos baseline
  std::optional<std::filesystem::path> csvPath;
  std::optional<std::filesystem::path> chartPath;
  bool quiet = false;  ///< no table, no progress line
};

}  // namespace fooball::cli
