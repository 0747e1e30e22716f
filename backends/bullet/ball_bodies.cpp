#include "ball_bodies.h"

#include "elastic_material.h"

namespace fooball::bullet_detail {

namespace {

btVector3 inertiaOf(const btSphereShape& shape, float mass) {
  btVector3 inertia(0.0f, 0.0f, 0.0f);
  shape.calculateLocalInertia(mass, inertia);
  return inertia;
}

}  // namespace

BallBody createBall(const BallDef& ball, std::size_t index, const BallSetup& setup) {
  BallBody created;
  created.shape = std::make_unique<btSphereShape>(static_cast<float>(ball.radius));
  const auto mass = static_cast<float>(ball.mass);
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, created.shape.get(),
                                                inertiaOf(*created.shape, mass));
  info.m_startWorldTransform.setOrigin(
      btVector3(static_cast<float>(ball.position.x), static_cast<float>(ball.position.y), 0.0f));
  info.m_linearDamping = setup.linearDamping;
  info.m_angularDamping = 0.0f;
  created.body = std::make_unique<btRigidBody>(info);
  btRigidBody& body = *created.body;
  makeElastic(body);
  body.setLinearFactor(btVector3(1.0f, 1.0f, 0.0f));
  body.setAngularFactor(0.0f);
  body.setActivationState(DISABLE_DEACTIVATION);
  body.setContactProcessingThreshold(setup.contactProcessingThreshold);
  body.setLinearVelocity(
      btVector3(static_cast<float>(ball.velocity.x), static_cast<float>(ball.velocity.y), 0.0f));
  tagBall(body, setup.counts, index);
  return created;
}

void setBallShape(BallBody& ball, double radius, double mass, const btVector3& gravity) {
  ball.shape->setUnscaledRadius(static_cast<float>(radius));
  const auto bulletMass = static_cast<float>(mass);
  ball.body->setMassProps(bulletMass, inertiaOf(*ball.shape, bulletMass));
  ball.body->updateInertiaTensor();
  ball.body->setGravity(gravity);
}

}  // namespace fooball::bullet_detail
