#pragma once

#include <limits>
#include <string>

#include "random_case.h"
#include "registry.h"

namespace fooball::robustness {

/// What a backend may do beyond the exact contract, and why: see tolerancesFor in case_run.cpp.
struct Tolerances {
  double energyRelative = 0.0;  ///< growth of an isolated case's energy, of the energy at start
  double energyAbsolute = 0.0;  ///< of Σ m·(|g|·r_max + v_max²), for rounding near zero energy
  double wallSlack = 0.0;       ///< m a centre may lie outside a closed box
  bool energyKeptUnderGravity = true;  ///< false: the energy is checked only without gravity
  /// false: under gravity, the energy is checked only with ball collisions off
  bool energyKeptUnderGravityWithCollisions = true;
};

Tolerances tolerancesFor(std::string_view backend);

/// The most work a backend may spend on one case. drawCase bounds a case's size, but some
/// backends' cost grows with what happens in the run (Box2D's energy blow-up under gravity, the
/// exact solver's event cascades in piles): such a case stops early, after the step in which
/// the backend's own count of its work passes `max`. The count is deterministic, so a seed still
/// reproduces the same run; see workCapFor in case_run.cpp for each cap and its cost.
struct WorkCap {
  std::string counter;   ///< a cumulative Backend::diagnostics() entry; "" for no cap
  bool perBall = false;  ///< the counter is weighted by (ball count + 1)
  double max = std::numeric_limits<double>::infinity();
};

WorkCap workCapFor(std::string_view backend);

/// Runs `c` on a new `backend` through the Simulation driver (at most until `cap` is passed)
/// and checks after every step: positions and velocities finite; ball count unchanged; in a
/// closed box, every centre inside the box (give or take the backend's wall slack). At the end
/// of an isolated case the total energy must not have grown by more than `tolerances`. Returns
/// the first violation, or "" when there is none.
std::string runCase(const RandomCase& c, const BackendInfo& backend, const Tolerances& tolerances,
                    const WorkCap& cap = {});

}  // namespace fooball::robustness
