#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "consistency/method_errors.h"
#include "interval.h"
#include "registry.h"
#include "robustness/case_limits.h"

/// What the test suites need to know about each backend, in one table keyed by registry name
/// (tests/backend_profiles.cpp): its tolerances and why, its error model, its pinned hash and
/// failure-map boundaries. The suites iterate registeredBackends() and ask profileFor(name);
/// no other test file names a backend in a branch or a list. A new backend is its folder, its
/// registry line and its row here.
namespace fooball::testing {

/// How far a backend may stray from exact answers in tests/conformance_test.cpp. Every row states
/// each value as measured × margin, or derived from the method's error; the defaults are derived
/// from double rounding (u = 2⁻⁵³ ≈ 1.1e-16 per operation).
struct ConformanceTolerances {
  /// |ΔP| relative to Σ m|v|, 300-ball gas with the walls off over 3 s. Default: ~940
  /// collisions, each rounding the pair's momenta by a few u (4 × 1.1e-16): 4e-13, so 1e-12.
  double momentum = 1e-12;
  /// Relative kinetic-energy change, either way, in a 300-ball gas without gravity over 5 s.
  /// Default: ~3'400 collisions and bounces, each rounding the energy by 4 u: 1.5e-12, so 3e-12.
  double energy = 3e-12;
  /// Relative total-energy change of the same gas under 9.81 m/s² over 5 s. A method that gains
  /// or loses energy there has its measured change pinned both ways. Default: as energy.
  Interval energyUnderGravity = eitherWay(3e-12);
  /// Relative, for the closed-form two-ball, kick and gravity answers. Default: a handful of
  /// roundings of O(1) values, 8 u ≈ 1e-15, so 2e-15.
  double velocity = 2e-15;
  /// m, for closed-form flight of a few metres. Default: 480 substeps of rounding at 20 m
  /// (½ ulp = 1.8e-15 m), 8.5e-13, so 1e-12.
  double position = 1e-12;
};

/// How closely a backend's wall count follows the bounces, in tests/wall_count_test.cpp. The
/// defaults hold for a method that turns a ball back in one step (the rule of
/// backends/common/wall_touches.h counts the rest).
struct WallCountBounds {
  /// The options the suite runs it with, a run spec's KEY=VALUE list ("": its defaults). An
  /// engine whose defaults move a resting pile or a gas's speeds (not its counting) is counted
  /// with the knob that fixes that, as in consistencyOptions.
  std::string_view options;
  /// New wall collisions per second in a pile of 320 balls at rest (88 of them against a wall),
  /// after its first second. Default: none, with room for one ball in a second whose contact
  /// jitters past the release distance.
  double restingPilePerSecond = 1.0;
  /// |counted − bounces| relative to the bounces, for the counted bounces of a 300-ball gas
  /// without collisions over 30 s (~1,600 bounces) against the paths' bounces and against the
  /// wall impulse / (2 m v_n). Default: the bounces under way at the end (a ball crosses in the
  /// last substep about once in the run) and rounding: 0.5%.
  double gasRelative = 0.005;
};

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

/// A random case (a drawCase seed beyond the default ones) whose energy the method changes far
/// beyond its bound for that world, or its worst default case: the measured change is pinned
/// both ways, so that the pin fails when the finding goes away and when it grows.
struct EnergyFinding {
  std::uint64_t seed = 0;   ///< 0: no finding
  Interval relativeChange;  ///< robustness::CaseOutcome::relativeEnergyChange()
};

/// Everything the suites need to know about one backend.
struct BackendProfile {
  std::string_view name;              ///< registry name (backends/registry.cpp)
  ConformanceTolerances conformance;  ///< tests/conformance_test.cpp
  WallCountBounds wallCount;          ///< tests/wall_count_test.cpp
  /// tests/consistency/short_time_test.cpp; methodError() fills in the solver step.
  MethodError methodError;
  /// tests/consistency: the options the backend runs with there, a run spec's KEY=VALUE list
  /// ("": its defaults). An engine set up as its users set it up (DESIGN.md) whose defaults do not
  /// keep a gas's energy has nothing there to agree on with the others; it is compared with the
  /// knob that fixes it, and every other suite runs its defaults.
  std::string_view consistencyOptions;
  /// tests/consistency/gas_statistics_test.cpp: relative kinetic-energy drift, either way, over
  /// the long run of a thermalised gas (at its end and on average over its snapshots).
  double gasEnergyDrift = 0.0;
  /// tests/consistency/gas_statistics_test.cpp: how far its collision rate lies from the others'
  /// by a known difference of its model (relative; 0: none), e.g. matter.js's circles, which are
  /// polygons. The backends' rates are compared with this taken out.
  double collisionRateOffset = 0.0;
  /// Why its long gas cannot agree with the others', as it is and with every option it has (an
  /// engine whose solver drains the energy with no knob to stop it: docs/accuracy.md), or empty.
  /// The gas statistics test then says so for its pairs, instead of comparing them.
  std::string_view gasStatisticsExemption;
  /// tests/robustness/random_invariants_test.cpp and the GUI monkey (tests/gui).
  robustness::Tolerances robustness;
  robustness::WorkCap workCap;  ///< tests/robustness/random_invariants_test.cpp
  /// tests/robustness/random_invariants_test.cpp: a finding kept in view (seed 0: none).
  EnergyFinding energyFinding;
  /// tests/robustness/determinism_test.cpp: the hash of the pinned scene's final state with
  /// default options. 0: not pinned yet (the test fails and prints the hash to pin).
  std::uint64_t determinismHash = 0;
  std::span<const BoundaryExpectation> failureMap;  ///< every sweep at least once
  /// One step of the app (1/60 s) can take minutes in states a user can reach (docs/accuracy.md):
  /// the GUI monkey, which waits for every step, adds no compare run of such a backend.
  bool stepsCanTakeMinutes = false;
  /// tests/robustness/random_invariants_test.cpp: how many of the default cases it runs (0: all;
  /// FOOBALL_SOAK runs all it asks). An engine in the Node.js host starts a Node.js process for
  /// every case (0.1–0.3 s), so it runs the first few, as many as CI's time allows.
  std::size_t randomCases = 0;
};

/// Every row of the table, in table order.
std::span<const BackendProfile> backendProfiles();

/// The row of the backend registered as `name`. Throws std::logic_error (so the test fails with
/// its message) when there is none: "backend 'X' has no row in tests/backend_profiles.cpp: state
/// its tolerances there".
const BackendProfile& profileFor(std::string_view name);

/// A new backend registered as `name` with `options`, a run spec's KEY=VALUE list ("": its
/// defaults), as a row gives them to a suite.
std::unique_ptr<Backend> createWithOptions(std::string_view name, std::string_view options);

}  // namespace fooball::testing
