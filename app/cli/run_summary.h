#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "fooball/backend.h"
#include "fooball/metrics.h"

namespace fooball::cli {

/// What `fooball-cli run` reports at the end of a run.
struct RunSummary {
  std::string sceneName;    ///< the scene's own name, may be empty
  std::string sceneSource;  ///< where it came from: "preset 'default'" or the file path
  std::string backendName;
  std::vector<std::string> changedOptions;  ///< "KEY=VALUE" for options not at their default
  std::size_t balls = 0;
  std::uint64_t steps = 0;
  double dt = 0.0;              ///< s
  double wallSeconds = 0.0;     ///< s, the whole stepping loop, metrics rows included
  double physicsSeconds = 0.0;  ///< s, inside Simulation::step only
  Metrics start;
  Metrics end;
  double startSpeedMomentum = 0.0;  ///< N·s, Σ m|v| at the start: the momentum scale
  std::vector<Diagnostic> diagnostics;
};

/// Aligned "key: value" lines: scene, backend, sizes, timing, conservation errors, counters
/// and the backend's diagnostics.
void printRunSummary(const RunSummary& summary, std::ostream& out);

}  // namespace fooball::cli
