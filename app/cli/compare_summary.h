#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fooball/metrics.h"

namespace fooball::cli {

/// What `compare` measured of one run (or of the chaos baseline).
struct ComparedRun {
  std::string label;  ///< the spec text, or "baseline"
  Metrics start;
  Metrics end;
  double startSpeedMomentum = 0.0;  ///< N·s, Σ m|v| at the start: the momentum scale of a gas
  double steppingSeconds = 0.0;     ///< wall-clock inside this run's own backend steps
  double rmsDivergence = 0.0;       ///< m, from run 0 at the end
  /// s: the first step after which the RMS divergence from run 0 exceeded the threshold.
  std::optional<double> departedAt;
};

/// The table `compare` prints.
struct CompareSummary {
  std::string sceneName;
  std::string sceneSource;  ///< the file path or "preset 'NAME'"
  std::size_t balls = 0;
  std::uint64_t steps = 0;
  double dt = 0.0;                    ///< s
  double departThreshold = 0.0;       ///< m, 10% of the mean radius
  double baselineDisplacement = 0.0;  ///< m, how far the baseline's balls start from run 0's
  std::vector<ComparedRun> runs;      ///< run 0 first, then the others, then the baseline
  bool hasBaseline = false;           ///< the last of `runs` is the baseline
};

void printCompareSummary(const CompareSummary& summary, std::ostream& out);

}  // namespace fooball::cli
