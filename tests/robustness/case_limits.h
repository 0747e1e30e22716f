#pragma once

#include <limits>
#include <string_view>

#include "interval.h"

namespace fooball::robustness {

/// What a backend may do beyond the exact contract in a random case; each backend's values and
/// their reasons are its row in tests/backend_profiles.cpp. Every bound is checked in both
/// directions where it has two: a method that starts losing energy fails as surely as one that
/// starts gaining it.
struct Tolerances {
  /// (E_end − E_start − the energy the method reports it changed) / E_start of an isolated case
  /// (no tools, edits, drag or world changes), E measured from the lowest point of the box, by
  /// the world the case runs in: without gravity; under gravity in a closed box with ball
  /// collisions off, and with them on; under gravity with a wall off (balls may fall out for
  /// good: a semi-implicit Euler method loses ½·m·|g|²·h per ball and second of free fall).
  testing::Interval energyWithoutGravity{0.0, 0.0};
  testing::Interval energyUnderGravity{0.0, 0.0};
  testing::Interval energyUnderGravityWithCollisions{0.0, 0.0};
  testing::Interval energyUnderGravityOpen{0.0, 0.0};
  double energyAbsolute = 0.0;  ///< of Σ m·(|g|·r_max + v_max²), either way, for rounding near 0 J
  /// A cumulative Backend::diagnostics() entry (J): energy the method says it changed by design,
  /// taken off the change before the check; "" for none.
  std::string_view reportedEnergyChange;
  double wallSlack = 0.0;  ///< m a centre may lie outside a closed box
  /// The deepest ball–ball overlap after a resolved step (below), as a fraction of the smaller
  /// radius, in a case whose ball collisions stay on: the method alone (an isolated case)…
  double ballOverlap = 0.0;
  /// … and with tools pressing balls together, edits, drag or world changes.
  double ballOverlapWithInteractions = 0.0;
  /// The deepest overlap of a ball with a wall after a resolved step, less wallSlack, as a
  /// fraction of the ball's radius, in a closed case (1: the centre on the wall).
  double wallOverlap = 0.0;
  /// The overlap bounds hold while every step so far was resolved: no ball travelled more than
  /// this many of the smallest radius per substep (speed × dt / substeps), before or after the
  /// step. At 0.5 two balls close by at most one smallest radius in a substep, so a time-stepped
  /// method finds every contact less than that deep; from 2 to 4 radii per substep it tunnels
  /// (tests/failure_map) and overlaps are as deep as the geometry allows. Infinite for an
  /// event-driven method. Nor do they hold once the method has cut a step short
  /// (BackendCounters::cutShortSteps), advancing it without resolving every contact by design.
  double resolvedTravel = 0.5;
};

/// The most work a backend may spend on one case. drawCase bounds a case's size, but some
/// backends' cost grows with what happens in the run (Box2D's energy blow-up under gravity, the
/// exact solver's event cascades in piles): such a case stops early, after the step in which
/// the backend's own count of its work passes `max`. The count is deterministic, so a seed still
/// reproduces the same run; each backend's cap and its cost are in tests/backend_profiles.cpp.
struct WorkCap {
  std::string_view counter;  ///< a cumulative Backend::diagnostics() entry; "" for no cap
  bool perBall = false;      ///< the counter is weighted by (ball count + 1)
  double max = std::numeric_limits<double>::infinity();
};

}  // namespace fooball::robustness
