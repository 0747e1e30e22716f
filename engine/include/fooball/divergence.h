#pragma once

#include "fooball/simulation.h"

namespace fooball {

/// How far one run has drifted from a reference run, ball by ball (same scene index). Same
/// scene, same dt, same forces: any difference is the methods' — or chaos (RunGroup's baseline).
struct Divergence {
  double rmsPositionDifference = 0.0;     ///< m, √(mean |p_run − p_reference|²)
  double maxPositionDifference = 0.0;     ///< m
  double energyDifference = 0.0;          ///< J, E_run − E_reference
  double relativeEnergyDifference = 0.0;  ///< (E_run − E_reference) / |E_reference|; 0 if E = 0
  double momentumDifference = 0.0;        ///< N·s, |P_run − P_reference|
};

/// O(N); balls beyond the smaller of the two counts are not compared.
Divergence measureDivergence(const Simulation& reference, const Simulation& run);

}  // namespace fooball
