#pragma once

#include <string>
#include <vector>

#include "fooball/method_limits.h"
#include "fooball/simulation.h"

namespace fooball {

/// The failure map's numbers for a run's state and settings now. O(N): the app evaluates them a
/// few times a second and fooball-cli once at the end, never per step.
struct LimitNumbers {
  /// Radii of the smallest ball that any two balls can close per solver step, Δv·h / r_min, Δv
  /// the diagonal of the velocities' bounding box (no pair closes faster, and it is never more
  /// than √2 times the fastest pair). A ball shot at a resting twin gives the map's v·h/r.
  double closingPerSolverStep = 0.0;
  /// |g|·h²/r_min where balls can pile up (ball collisions on, a wall on where gravity points),
  /// else 0.
  double pileSinkPerSolverStep = 0.0;
  double packingFraction = 0.0;  ///< Σ π r² / box area
  /// The method's own error, relativeEnergyError (fooball/metrics.h); NaN where E(0) is 0.
  double relativeEnergyError = 0.0;
};

/// Needs the run's backend (its substeps): not while a step is out (Simulation::stepping()).
LimitNumbers measureLimitNumbers(const Simulation& run);

enum class MethodLimit { Tunnelling, RestingPile, Packing, EnergyError };

/// The relative energy error (either sign) the check allows before it says so, whatever the
/// cause: the catch-all for failures no mapped limit explains.
inline constexpr double kEnergyErrorLimit = 0.1;

/// The relative energy error (either sign) from which the app points out a run's energy error,
/// long before kEnergyErrorLimit calls its trajectory untrustworthy: 1 % is where a user would
/// care. It is a visible step of the total on the energy chart (several px of a plot 160 px
/// tall, where rounding-level methods draw a flat line), 10× the 1e-3 the failure map's sweeps
/// call a failure, and far above anything chaos does: chaos moves the balls but keeps the
/// energy, so the chaos baseline's residual is rounding (about 1e-15), and any 1 % is the
/// method's own. chipmunk on the default preset reaches it within seconds (3.1 % in 12 s).
inline constexpr double kNoticeableEnergyError = 0.01;

struct CrossedLimit {
  MethodLimit limit;
  double value = 0.0;       ///< the run's number now (LimitNumbers; |relative energy error|)
  double boundary = 0.0;    ///< MeasuredBoundary::failsFrom, or kEnergyErrorLimit
  double passesUpTo = 0.0;  ///< the map's last passing point; 0 if none, or the energy error
};

/// The limits of `limits` that `numbers` reach (at or beyond the first measured failure), and the
/// energy error beyond kEnergyErrorLimit.
std::vector<CrossedLimit> crossedLimits(const LimitNumbers& numbers, const MethodLimits& limits);
/// Both at once: what the app and fooball-cli call.
std::vector<CrossedLimit> crossedLimits(const Simulation& run, const MethodLimits& limits);

/// "tunnelling", "resting pile", "dense packing", "energy error".
std::string limitName(MethodLimit limit);
/// One line naming each crossed limit with its number and boundary; empty when none. fooball-cli
/// writes it to stderr as a warning, beside cutShortNotice.
std::string methodLimitNotice(const std::vector<CrossedLimit>& crossed);
/// A few sentences for a tooltip: what the limit is, the run's number, the measured boundary,
/// and what to do.
std::string limitExplanation(const CrossedLimit& crossed);

}  // namespace fooball
