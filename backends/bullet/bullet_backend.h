#pragma once

#include <memory>
#include <string_view>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeBulletBackend();

/// The registry's line for the Bullet backend: the engine and its version as btGetVersion()
/// reports it (bullet_backend.cpp checks the two agree), and how it is set up.
inline constexpr std::string_view kBulletDescription =
    "Bullet 3.24 (btGetVersion 324), a 3D engine held to the plane: restitution 1, frictionless "
    "spheres, its solver's own defaults";

/// Where the Bullet adapter was measured to stop being right (docs/accuracy.md, the "Where"
/// tables of "Tunnelling", "Resting pile under strong gravity" and "Dense packing", at its
/// default 1 substep). Filled in from the failure map's sweeps.
inline constexpr MethodLimits kBulletLimits{};

}  // namespace fooball
