#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fooball/presets.h"

namespace fooball::cli {

inline constexpr std::string_view kDefaultBackend = "elastic";

/// Upper bound on the steps one `run` may take: far beyond any useful run (a day at 10 kHz is
/// ~1e9), small enough that a typo such as --dt 1e-300 fails at once instead of running forever.
inline constexpr std::uint64_t kMaxRunSteps = 1'000'000'000;

/// Everything `fooball-cli run` was asked to do, as parsed; checked by runCommand.
struct RunOptions {
  std::optional<std::filesystem::path> scenePath;  ///< --scene; the preset when absent
  std::string presetName{kDefaultPreset};
  /// --backend, a run spec (fooball/run_spec.h): NAME[:KEY=VALUE[,KEY=VALUE]...].
  std::string backendSpec{kDefaultBackend};
  double duration = 10.0;    ///< s of simulated time
  std::optional<double> dt;  ///< s; the scene's own (Scene::dt, else kDefaultDt) when absent
  /// --substeps N: sets the backend's substeps option after the spec's assignments.
  std::optional<std::string> substeps;
  std::vector<std::string> assignments;  ///< --option KEY=VALUE, applied in order after those
  std::optional<std::filesystem::path> metricsPath;
  std::int64_t every = 1;  ///< steps between metrics rows
  std::optional<std::filesystem::path> savePath;
  bool quiet = false;  ///< no summary, no progress line
};

}  // namespace fooball::cli
