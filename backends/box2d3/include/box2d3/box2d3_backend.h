#pragma once

#include <memory>
#include <string>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

/// Box2D v3 (npm box2d3-wasm 5.2.0, WebAssembly without threads) in the Node.js host, set up as
/// its users set it up for restitution 1 (backends/js/adapters/box2d3.js says what it sets and
/// why).
std::unique_ptr<Backend> makeBox2d3Backend();

/// Why Box2D v3 cannot run here, with the fix; empty when it can.
std::string box2d3Unavailable();

/// Where Box2D v3 at its users' settings was measured to stop being right (docs/accuracy.md; one
/// Box2D step per step, quick grid): it never tunnelled up to 16 radii per step with 0.05 m balls
/// (speculative contacts), but 0.5 m balls from 2.38.
inline constexpr MethodLimits kBox2d3Limits{
    .tunnelling = MeasuredBoundary{2.0, 2.38},  // v·h/r: passes up to 2, fails from 2.38
    // g: passes up to 10 m/s², fails from 100 m/s² (energy and overlap).
    .restingPile = MeasuredBoundary{pileSweepNumber(10.0, 1), pileSweepNumber(100.0, 1)},
    .packing = MeasuredBoundary{0.0, 0.277},  // fails from the lowest tried (energy, overlap)
};

}  // namespace fooball
