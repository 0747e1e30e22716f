#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>

#include "contact_counter.h"
#include "fooball/scene.h"

namespace fooball::bullet_detail {

/// One ball: a sphere shape of its own (so an edit can change one ball's radius) and a dynamic
/// rigid body, not yet in a world.
struct BallBody {
  std::unique_ptr<btSphereShape> shape;
  std::unique_ptr<btRigidBody> body;
};

/// What the balls share, set on every ball body.
struct BallSetup {
  float linearDamping = 0.0f;               ///< Bullet's d (linear_damping.h)
  float contactProcessingThreshold = 0.0f;  ///< m (contact_processing.h)
  ContactCounts* counts = nullptr;          ///< where its contacts count (contact_counter.h)
};

/// Creates a ball as a Bullet user holds a sphere to the plane z = 0 with only what a ball needs:
/// - linear factor (1, 1, 0): the solver never moves it along z (gravity and every contact
///   normal lie in the plane anyway, sphere centres all at z = 0); angular factor 0: no impulse
///   spins it, so no energy goes into rotation. Bullet has no 2D mode: these two factors are
///   its documented way to constrain a body to a plane;
/// - mass: the scene's, rounded to float, with the solid sphere's inertia (calculateLocalInertia)
///   that the zero angular factor leaves unused;
/// - restitution 1 and friction 0 of every kind (elastic_material.h);
/// - never deactivated (DISABLE_DEACTIVATION): a sleeping ball would ignore drag and tools, and
///   Bullet puts bodies slower than 0.8 m/s to sleep after 2 s by default.
/// Continuous collision stays off, Bullet's default (wall_containment.h says why).
/// `index`: its scene index (contact_counter.h).
BallBody createBall(const BallDef& ball, std::size_t index, const BallSetup& setup);

/// Gives the ball radius `radius` (m) and mass `mass` (kg), keeping its body in the world;
/// `gravity` (m/s²) is the world's, which Bullet stores per body as a force (mass times it).
void setBallShape(BallBody& ball, double radius, double mass, const btVector3& gravity);

}  // namespace fooball::bullet_detail
