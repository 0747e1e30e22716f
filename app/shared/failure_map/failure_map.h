#pragma once

#include <functional>
#include <span>
#include <stop_token>
#include <string_view>
#include <vector>

#include "registry.h"
#include "sweep_point.h"

namespace fooball::failure_map {

/// One sweep of the failure map (docs/accuracy.md): what it varies, what it measures and where
/// it draws the line between passing and failing. The texts hold no commas: they are CSV fields.
struct SweepSpec {
  std::string_view name;           ///< --sweep, CSV, chart file failure-<name>.png
  std::string_view title;          ///< one line for the table and the chart
  std::string_view parameterName;  ///< with its unit, e.g. "v·h / r (solver step per radius)"
  std::string_view errorName;      ///< with its unit
  double threshold = 0.0;          ///< an error above this fails
  double overlapLimit = 0.0;       ///< an overlap above this (fraction of r) fails; inf: unchecked
  bool harderAbove = true;         ///< larger parameters are harder (else smaller ones are)
  bool logParameter = true;        ///< the grid spans decades (else a linear axis shows it)
  std::vector<SweepPoint> (*run)(std::string_view backend, bool quick) = nullptr;
};

/// Every sweep, in the order the map shows them.
std::span<const SweepSpec> sweepSpecs();

/// The sweep called `name`; throws std::invalid_argument listing the known names.
const SweepSpec& findSweep(std::string_view name);

/// Runs `spec` on `backend` and judges every point against the spec's limits.
std::vector<SweepPoint> runSweep(const SweepSpec& spec, std::string_view backend, bool quick);

/// Where a failure map run is, for a progress line.
struct FailureMapProgress {
  const SweepSpec* sweep = nullptr;  ///< the sweep starting
  std::string_view backend;          ///< on this backend
  double fraction = 0.0;             ///< of all sweeps on all backends finished, in [0, 1)
};

/// Runs every sweep of `sweeps` on every backend, sweep by sweep, reporting each sweep on each
/// backend before it starts. A stop request ends the run before the next sweep on a backend;
/// the points measured so far are returned.
std::vector<SweepPoint> runFailureMap(
    std::span<const SweepSpec* const> sweeps, std::span<const BackendInfo> backends, bool quick,
    const std::function<void(const FailureMapProgress&)>& progress = {}, std::stop_token stop = {});

}  // namespace fooball::failure_map
