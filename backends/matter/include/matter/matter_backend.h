#pragma once

#include <memory>
#include <string>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

/// matter.js 0.20.0 in the Node.js host, set up as its users set it up for restitution 1
/// (backends/js/adapters/matter.js says what it sets and why, and its scale of 64 px/m).
std::unique_ptr<Backend> makeMatterBackend();

/// Why matter.js cannot run here, with the fix; empty when it can.
std::string matterUnavailable();

/// Where matter.js at its users' settings was measured to stop being right (docs/accuracy.md, the
/// "Where" tables; one matter step per step). Its resting threshold (2 px per frame, 1.9 m/s)
/// makes the map's slow scenes fail from their easiest point.
inline constexpr MethodLimits kMatterLimits{
    .tunnelling = MeasuredBoundary{2.0, 2.83},  // v·h/r: passes up to 2, fails from 2.83
    // None in g·h²/r: the pile sweep fails at every g tried (from 1 m/s²), by the resting
    // threshold, a speed, not by how far gravity sinks a ball per step.
    .restingPile = std::nullopt,
    .packing = MeasuredBoundary{0.0, 0.277},  // fails from the lowest tried (energy)
};

}  // namespace fooball
