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
/// defaults): at the easiest point of every sweep. It finds contacts where a step starts, a
/// step's travel deep, and turns overlaps shallower than 4 cm into speed (split_impulse.h).
inline constexpr MethodLimits kBulletLimits{
    // v·h/r, the 0.05 m ball: its shallow overlaps gain energy from the lowest tried (0.5).
    .tunnelling = MeasuredBoundary{0.0, 0.5},
    // g: the energy error is 3.1 Σ m·g·r already at 1 m/s² (one Bullet step a frame).
    .restingPile = MeasuredBoundary{0.0, pileSweepNumber(1.0, 1)},
    // r = 0.1 m: the energy grows by 109% at the lowest packing tried.
    .packing = MeasuredBoundary{0.0, 0.28},
};

}  // namespace fooball
