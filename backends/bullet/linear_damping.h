#pragma once

#include "fooball/vec2.h"

namespace fooball::bullet_detail {

/// Bullet's linear damping is a fraction lost per second, not a rate: each Bullet step of h
/// seconds multiplies a body's velocity by (1 − d)^h (btRigidBody::applyDamping), after adding
/// the step's gravity (integrateVelocities) and before the contacts are solved. For the scene's
/// dv/dt = −c·v the exact factor over h is exp(−c·h), so d = 1 − exp(−c). Unlike Box2D's Padé
/// factor (backends/box2d/linear_damping.h) this does not depend on h: it is set once when c
/// changes. A user handing Bullet c itself would damp by (1 − c)^h, too much by a factor
/// −ln(1 − c)/c ≈ 1 + c/2 for small c, and for c ≥ 1 (Bullet clamps d to [0, 1] in setDamping)
/// stop every ball dead each step. d = 1 − exp(−c) lies in [0, 1) for every c ≥ 0.
float bulletLinearDamping(double airResistance);

/// The factor one Bullet step of `bulletStep` s multiplies velocities by, evaluated in btScalar
/// exactly as applyDamping does, so the energy booked is the energy Bullet removes.
double bulletDampingFactor(float linearDamping, float bulletStep);

/// J: the kinetic energy one Bullet step's damping takes from a ball of `mass` (kg) moving at
/// `velocity` (m/s) before the step, under `gravity` (m/s²): ½ m |v + h·g|² (1 − factor²).
inline double dampingLoss(Vec2 velocity, double mass, Vec2 gravity, double bulletStep,
                          double factor) {
  return 0.5 * mass * lengthSquared(velocity + gravity * bulletStep) * (1.0 - factor * factor);
}

}  // namespace fooball::bullet_detail
