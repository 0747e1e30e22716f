#pragma once

#include <memory>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeElasticBackend();

/// Where the elastic solver was measured to stop being right (docs/accuracy.md, the "Where"
/// tables of "Tunnelling", "Resting pile under strong gravity" and "Dense packing", at its
/// default 4 substeps). It never tunnels a wall and holds every mass ratio and scale tried.
inline constexpr MethodLimits kElasticLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r: passes up to 2, fails from 2.38
    // g: passes up to 31.6 m/s², fails from 100 m/s² (energy and overlap).
    .restingPile = MeasuredBoundary{pileSweepNumber(31.6, 4), pileSweepNumber(100.0, 4)},
    .packing = MeasuredBoundary{0.711, 0.758},  // r = 0.1 m: overlap beyond 0.1 r from 0.758
};

}  // namespace fooball
