#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "consistency/method_errors.h"
#include "robustness/case_limits.h"

/// What the test suites need to know about each backend, in one table keyed by registry name
/// (tests/backend_profiles.cpp): its tolerances and why, its error model, its pinned hash and
/// failure-map boundaries. The suites iterate registeredBackends() and ask profileFor(name);
/// no other test file names a backend in a branch or a list. A new backend is its folder, its
/// registry line and its row here.
namespace fooball::testing {

/// How far a backend may stray from exact answers in tests/conformance_test.cpp.
struct ConformanceTolerances {
  double momentum = 1e-12;  ///< relative to Σ m|v|
  double energy = 1e-9;     ///< relative kinetic-energy change in a no-gravity gas over 5 s
  double velocity = 1e-9;   ///< relative, for closed-form two-ball and kick answers
  double position = 1e-9;   ///< m
};

/// A closed range [low, high].
struct Interval {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();

  constexpr bool contains(double value) const { return value >= low && value <= high; }
};

/// [centre − halfWidth, centre + halfWidth].
constexpr Interval around(double centre, double halfWidth) {
  return {centre - halfWidth, centre + halfWidth};
}

/// Every point whose parameter is at or below `atOrBelow` has an error above `error`.
struct ErrorFloor {
  double atOrBelow = 0.0;
  double error = 0.0;
};

/// One pinned fact about a backend's curve(s) of a failure-map sweep (app/shared/failure_map,
/// docs/accuracy.md), checked by tests/failure_map/pinned_boundaries_test.cpp. Unset fields
/// check nothing. Tunnelling runs its full grid; every other sweep its `--quick` grid.
struct BoundaryExpectation {
  std::string_view sweep;    ///< failure_map::SweepSpec::name, e.g. "tunnelling"
  std::string_view variant;  ///< one curve (SweepPoint::variant), or "" for every curve
  double maxError = std::numeric_limits<double>::infinity();  ///< above every point's error
  bool passesEverywhere = false;
  std::optional<double> passesBelow;     ///< every point with a parameter below this passes
  std::optional<double> passesAbove;     ///< every point with a parameter above this passes
  std::optional<double> failsAbove;      ///< every point with a parameter above this fails
  std::optional<ErrorFloor> errorFloor;  ///< where the points fail by much more than rounding
  /// Where the curve's boundary (failure_map::locateBoundaries) lies; one curve only.
  std::optional<Interval> lastPass;
  std::optional<Interval> firstFail;
};

/// Everything the suites need to know about one backend.
struct BackendProfile {
  std::string_view name;              ///< registry name (backends/registry.cpp)
  ConformanceTolerances conformance;  ///< tests/conformance_test.cpp
  /// tests/consistency/short_time_test.cpp; methodError() fills in the solver step.
  MethodError methodError;
  /// tests/consistency/gas_statistics_test.cpp: relative kinetic-energy drift over the long run
  /// of a thermalised gas.
  double gasEnergyDrift = 0.0;
  /// tests/robustness/random_invariants_test.cpp and the GUI monkey (tests/gui).
  robustness::Tolerances robustness;
  robustness::WorkCap workCap;  ///< tests/robustness/random_invariants_test.cpp
  /// A random case (seed) whose energy grows under gravity when checked strictly: the finding
  /// behind robustness.energyKeptUnderGravity(WithCollisions) = false, pinned so that the
  /// exemption goes when the finding does. 0: the backend has no such exemption.
  std::uint64_t energyGainSeed = 0;
  /// tests/robustness/determinism_test.cpp: the hash of the pinned scene's final state with
  /// default options. 0: not pinned yet (the test fails and prints the hash to pin).
  std::uint64_t determinismHash = 0;
  std::span<const BoundaryExpectation> failureMap;  ///< every sweep at least once
  /// One step of the app (1/60 s) can take minutes in states a user can reach (docs/accuracy.md):
  /// the GUI monkey, which waits for every step, adds no compare run of such a backend.
  bool stepsCanTakeMinutes = false;
};

/// Every row of the table, in table order.
std::span<const BackendProfile> backendProfiles();

/// The row of the backend registered as `name`. Throws std::logic_error (so the test fails with
/// its message) when there is none: "backend 'X' has no row in tests/backend_profiles.cpp: state
/// its tolerances there".
const BackendProfile& profileFor(std::string_view name);

}  // namespace fooball::testing
