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
/// Box2D step per step, quick grid).
inline constexpr MethodLimits kBox2d3Limits{};

}  // namespace fooball
