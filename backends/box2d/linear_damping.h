#pragma once

#include "fooball/vec2.h"
#include "velocity_scan.h"

namespace fooball::box2d_detail {

/// Box2D's linear damping is not exponential: each Box2D step of h seconds multiplies a body's
/// velocity by 1/(1 + h·c') (a Padé approximation of exp(−c·h)), so giving bodies the scene's
/// air resistance c would decay too slowly (by ~(c·h)²/2 per step). This returns the c' (1/s)
/// for which the factor is exactly exp(−c·h): c' = (exp(c·h) − 1)/h. It depends on h, so it is
/// recomputed whenever the Box2D step changes.
float box2dLinearDamping(double airResistance, float box2dStep);

/// The factor Box2D multiplies velocities by in one step, evaluated in float exactly as
/// b2Island::Solve does, so the energy booked is the energy Box2D removes.
float box2dDampingFactor(float linearDamping, float box2dStep);

/// J: the kinetic energy one Box2D step's damping removes. b2Island::Solve adds h·g to each
/// velocity, then multiplies by the factor d, then solves contacts, so each ball loses
/// ½ m |v + h g|² (1 − d²). Summed from the sums of the velocities before the step:
/// Σ m|v + h g|² = Σ m|v|² + 2h g·Σ m v + h²|g|² Σ m.
double dampingLoss(const VelocityScan& before, double totalMass, Vec2 gravity, double box2dStep,
                   double dampingFactor);

}  // namespace fooball::box2d_detail
