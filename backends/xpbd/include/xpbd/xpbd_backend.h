#pragma once

#include <memory>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeXpbdBackend();

/// Where the XPBD solver was measured to stop being right (docs/accuracy.md, the "Where" tables
/// of "Tunnelling", "Resting pile under strong gravity" and "Dense packing", at its default 8
/// substeps). It never tunnels a wall.
inline constexpr MethodLimits kXpbdLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r: passes up to 2, fails from 2.38
    // g: passes up to 316 m/s², fails from 1000 m/s² (energy and overlap).
    .restingPile = MeasuredBoundary{pileSweepNumber(316.0, 8), pileSweepNumber(1000.0, 8)},
    .packing = MeasuredBoundary{0.284, 0.379},  // r = 0.1 m: energy error 7.2e-3 from 0.379
};

}  // namespace fooball
