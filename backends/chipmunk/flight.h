#pragma once

#include <chipmunk/chipmunk.h>

#include <span>

#include "fooball/vec2.h"

namespace fooball::chipmunk_detail {

/// Gravity and air resistance, applied by the adapter to every ball's velocity *before* each
/// Chipmunk step, while the space itself runs with gravity 0 and damping 1. Two traps:
///
/// - Chipmunk integrates positions first (cpSpaceStep: position_func for every body, then
///   collision detection, then velocity_func with gravity, then the impulse solver). With the
///   space's gravity, a step reports x' = x + h·v beside v' = v + h·g: explicit Euler, whose
///   positions follow the parabola of a launch velocity h·g/2 *below* the reported one — the
///   opposite error of Box2D's semi-implicit Euler — and the bounce target (cpArbiterPreStep,
///   e times the approach speed before the velocity update) misses that step's h·g. Adding h·g
///   here first makes the step x' = x + h·(v + h·g), v' = v + h·g + contact impulses:
///   semi-implicit Euler, the same as Box2D's, and a bounce reflects the whole approach speed.
/// - Chipmunk's damping multiplies velocities by damping^h each step (cpSpaceStep:
///   cpfpow(space->damping, dt)), which is exact for dv/dt = −c·v with damping = e^{−c}, but its
///   loss is nowhere to be read. Here the factor is e^{−c·h}, applied after the gravity kick
///   (v' = (v + h·g)·e^{−c·h}, the order Box2D uses), and each ball's loss ½m(|v + h·g|² − |v'|²)
///   is summed exactly into BackendCounters::dragLoss.
///
/// Returns the energy (J) the drag took in this kick. `masses` (kg) in the order of `balls`.
double kickVelocities(std::span<cpBody* const> balls, std::span<const double> masses, Vec2 gravity,
                      double airResistance, double step);

}  // namespace fooball::chipmunk_detail
