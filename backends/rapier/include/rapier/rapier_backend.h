#pragma once

#include <memory>
#include <string>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

/// Rapier 2D in the Node.js host, 0.21.0 or 0.19.3 (option `version`), set up as its users set it
/// up for restitution 1 (backends/js/adapters/rapier.js says what it sets and why).
std::unique_ptr<Backend> makeRapierBackend();

/// Why Rapier cannot run here, with the fix; empty when it can.
std::string rapierUnavailable();

/// Where Rapier 2D 0.21.0 at its users' settings was measured to stop being right
/// (docs/accuracy.md; one Rapier step per step, quick grid): it never tunnelled up to 16 radii
/// per step with 0.05 m balls (predictive contacts), but 0.5 m balls from 2.38.
inline constexpr MethodLimits kRapierLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r: passes up to 2, fails from 2.38
    // g: passes up to 10 m/s², fails from 100 m/s² (energy and overlap).
    .restingPile = MeasuredBoundary{pileSweepNumber(10.0, 1), pileSweepNumber(100.0, 1)},
    .packing = MeasuredBoundary{0.0, 0.277},  // fails from the lowest tried (energy, overlap)
};

}  // namespace fooball
