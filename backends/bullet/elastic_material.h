#pragma once

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>

namespace fooball::bullet_detail {

/// Restitution 1 and no friction of any kind on a ball or a wall, as a Bullet user who wants
/// restitution 1 sets them. Bullet combines a pair's restitutions and frictions as products
/// (btManifoldResult's calculateCombinedRestitution, calculateCombinedFriction, and the rolling
/// and spinning ones): restitution 1 on both sides gives 1, friction 0 on both gives 0. The
/// body defaults this changes: restitution 0, friction 0.5 (btRigidBodyConstructionInfo).
inline void makeElastic(btCollisionObject& object) {
  object.setRestitution(1.0f);
  object.setFriction(0.0f);
  object.setRollingFriction(0.0f);
  object.setSpinningFriction(0.0f);
}

/// The solver's public restitution threshold: a contact closing slower than
/// m_restitutionVelocityThreshold (default 0.2 m/s) gets restitution 0 (restitutionCurve in
/// btSequentialImpulseConstraintSolver.cpp), which would make every slow hit, and every hop of a
/// ball resting under gravity, perfectly inelastic. Set to 0, as the settings rule asks of public
/// restitution thresholds (DESIGN.md, "Engines as their users set them up").
inline void removeRestitutionThreshold(btContactSolverInfo& solverInfo) {
  solverInfo.m_restitutionVelocityThreshold = 0.0f;
}

}  // namespace fooball::bullet_detail
