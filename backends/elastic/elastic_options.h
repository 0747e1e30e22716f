#pragma once

#include <cstddef>
#include <vector>

#include "fooball/options.h"

namespace fooball::elastic {

/// The elastic backend's options as the world uses them: read once when an option changes, never
/// per step.
struct ElasticSettings {
  int substeps = 4;  ///< solver substeps per step
  int threads = 1;   ///< worker threads per step, at most
  /// Balls each worker beyond the first needs before it joins a step (0: every thread, always).
  /// A worker adds a barrier wait to every phase of a substep: ~15 µs on an idle two-core
  /// machine, but up to a scheduler time slice when another process holds the other core, so
  /// beside two busy processes two workers on the 38-ball default scene take 11.8 ms a step
  /// against 0.9 µs for one. At 600'000 balls (two workers) they are 1.1–1.8× faster than one,
  /// idle or busy, and at 300'000 (one worker) this gives up the 2.1× that two would gain on an
  /// idle machine (docs/performance.md).
  std::size_t ballsPerThread = 250'000;
};

/// The option specs the backend registers, with ElasticSettings' defaults.
std::vector<OptionSpec> elasticOptionSpecs();

/// `options` must hold the specs of elasticOptionSpecs(); OptionSet has checked the ranges.
ElasticSettings readElasticSettings(const OptionSet& options);

}  // namespace fooball::elastic
