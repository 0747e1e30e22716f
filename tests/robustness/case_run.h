#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "case_limits.h"
#include "random_case.h"
#include "registry.h"

namespace fooball::robustness {

/// The robustness tolerances of `backend` (its row in tests/backend_profiles.cpp). Fails the
/// test (throws) for a backend without a row.
Tolerances tolerancesFor(std::string_view backend);

/// The work cap of `backend` (its row in tests/backend_profiles.cpp).
WorkCap workCapFor(std::string_view backend);

/// Which energy bound of Tolerances an isolated case answers to; None for a case whose energy is
/// not the method's alone (tools, edits, drag or world changes).
enum class EnergyWorld {
  None,
  WithoutGravity,
  UnderGravity,                ///< in a closed box, ball collisions off
  UnderGravityWithCollisions,  ///< in a closed box
  UnderGravityOpen,            ///< a wall off
};

/// What one random case did on one backend.
struct CaseOutcome {
  /// The first broken invariant of a step, "" when none: a position or velocity not finite, the
  /// ball count changed, or in a closed box a centre further outside than the wall slack. The
  /// run stops there.
  std::string stepViolation;
  bool isolated = false;  ///< no tools, edits, drag or world changes (RandomCase::isolated)
  int stepsRun = 0;
  bool stoppedByWorkCap = false;  ///< the run ended early, at the backend's work cap
  EnergyWorld energyWorld = EnergyWorld::None;
  double startEnergy = 0.0;  ///< J, kinetic plus potential above the lowest point of the box
  double endEnergy = 0.0;    ///< J, the same after the last step run
  double reportedEnergyChange = 0.0;  ///< J, Tolerances::reportedEnergyChange at the end
  double energyScale = 0.0;           ///< J, Σ m·(|g|·r_max + v_max²) at the start (Tolerances)
  /// Steps whose overlaps were measured: the resolved ones from the start (Tolerances).
  int resolvedSteps = 0;
  /// The deepest ball–ball overlap after a resolved step (fraction of the smaller radius) and
  /// that step, in a case whose ball collisions stay on (step −1: none measured).
  double ballOverlap = 0.0;
  int ballOverlapStep = -1;
  /// The deepest ball–wall overlap after a resolved step, less the wall slack (fraction of the
  /// ball's radius) and that step, in a closed case (step −1: none measured).
  double wallOverlap = 0.0;
  int wallOverlapStep = -1;
  /// How the state after the last step, saved as File → Save writes it (Simulation::savedScene),
  /// failed to reopen bit for bit through writeScene and parseScene; "" when it did.
  std::string reopenError;

  /// (E_end − E_start − the reported change) / E_start.
  double relativeEnergyChange() const {
    return (endEnergy - startEnergy - reportedEnergyChange) / startEnergy;
  }
};

/// Runs `c` on a new `backend` through the Simulation driver (at most until `cap` is passed),
/// checks the invariants of every step (stepViolation, with `tolerances.wallSlack`) and measures
/// the rest of the outcome.
CaseOutcome runCase(const RandomCase& c, const BackendInfo& backend, const Tolerances& tolerances,
                    const WorkCap& cap = {});

/// The first bound of `tolerances` that `outcome` breaks, described, or "" when none: the step
/// invariants, the energy of an isolated case in both directions, the ball–ball and ball–wall
/// overlaps, and the saved state's reopening.
std::string violationOf(const CaseOutcome& outcome, const Tolerances& tolerances);

}  // namespace fooball::robustness
