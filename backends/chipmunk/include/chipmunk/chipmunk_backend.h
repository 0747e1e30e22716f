#pragma once

#include <memory>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeChipmunkBackend();

/// Where the Chipmunk2D adapter was measured to stop being right (docs/accuracy.md, the "Where"
/// tables of "Tunnelling", "Resting pile under strong gravity" and "Dense packing", at its
/// default 4 substeps). It never tunnels a wall.
inline constexpr MethodLimits kChipmunkLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r: passes up to 2, fails from 2.38
    // g: passes up to 31.6 m/s², fails from 100 m/s² (energy and overlap).
    .restingPile = MeasuredBoundary{pileSweepNumber(31.6, 4), pileSweepNumber(100.0, 4)},
    // r = 0.1 m: fails from the lowest packing tried (overlap 0.11 r).
    .packing = MeasuredBoundary{0.0, 0.28},
};

}  // namespace fooball
