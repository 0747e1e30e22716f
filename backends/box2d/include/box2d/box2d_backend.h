#pragma once

#include <memory>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeBox2dBackend();

/// Where the Box2D adapter was measured to stop being right (docs/accuracy.md, the "Where"
/// tables of "Tunnelling", "Resting pile under strong gravity" and "Dense packing", at its
/// default 4 substeps). auto_substeps keeps balls with 2r > 0.5 m from tunnelling; the limit is
/// the small ball's, which tunnels at any speed beyond 2r per substep.
inline constexpr MethodLimits kBox2dLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r, the 0.05 m ball
    // g: passes up to 1 m/s², fails from 3.16 m/s² (energy).
    .restingPile = MeasuredBoundary{pileSweepNumber(1.0, 4), pileSweepNumber(3.16, 4)},
    // r = 0.1 m: fails from the lowest packing tried (overlap 0.11 r).
    .packing = MeasuredBoundary{0.0, 0.28},
};

}  // namespace fooball
