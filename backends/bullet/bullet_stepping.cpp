// The step loop of BulletAdapter: impulses, then per Bullet step the drag accounting, one
// stepSimulation of exactly dt/substeps seconds, the walls' impulse and the wall containment
// (wall_containment.h).

#include "bullet_adapter.h"
#include "linear_damping.h"
#include "plane_vectors.h"
#include "wall_containment.h"

namespace fooball::bullet_detail {

void BulletAdapter::step(double dt, std::span<const Vec2> forces) {
  if (!forces.empty()) applyImpulses(dt, forces);
  const auto bulletStep = static_cast<float>(dt / settings_.substeps);  // s
  btDiscreteDynamicsWorld& world = world_->get();
  const Walls& on = worldSettings_.walls;
  const bool anyWall = on.left || on.right || on.bottom || on.top;
  WallContainment walls(box_, on, fromBullet(world.getGravity()));
  int stepsTaken = 0;
  while (stepsTaken < settings_.substeps && !stopRequested()) {
    if (worldSettings_.airResistance > 0.0) dragLoss_ += dragLossOfStep(bulletStep);
    // maxSubSteps 0: one step of exactly bulletStep. A user's stepSimulation(dt, maxSubSteps,
    // fixedTimeStep) takes the same fixed steps, but keeps the remainder of dt that is not a whole
    // number of them for the next call and reports motion states interpolated between steps; the
    // bodies here are read directly, at the end of a whole step.
    world.stepSimulation(bulletStep, 0);
    addWallImpulse(*world.getDispatcher(), contacts_);
    if (anyWall) {
      for (std::size_t i = 0; i < balls_.size(); ++i) {
        walls.contain(*balls_[i].body, masses_[i], balls_[i].shape->getRadius(),
                      contacts_.touches[i]);
      }
    }
    ++stepsTaken;
  }
  bulletSteps_ += static_cast<std::uint64_t>(stepsTaken);
  ballsBroughtBack_ += walls.ballsBroughtBack();
  contacts_.wallCollisions += walls.wallCollisions();
  contacts_.wallImpulse += walls.impulse();
}

void BulletAdapter::applyImpulses(double dt, std::span<const Vec2> forces) {
  // Velocity is set directly, not through btRigidBody::applyCentralImpulse, so the change is
  // forces[i]·dt / m with the scene's mass, exactly as the driver books the work.
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    btRigidBody& body = *balls_[i].body;
    body.setLinearVelocity(
        toBullet(fromBullet(body.getLinearVelocity()) + forces[i] * (dt / masses_[i])));
  }
}

double BulletAdapter::dragLossOfStep(float bulletStep) const {
  const double factor = bulletDampingFactor(linearDamping_, bulletStep);
  // The float gravity Bullet integrates with.
  const Vec2 gravity = fromBullet(world_->get().getGravity());
  double loss = 0.0;  // J
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    loss += dampingLoss(fromBullet(balls_[i].body->getLinearVelocity()), masses_[i], gravity,
                        static_cast<double>(bulletStep), factor);
  }
  return loss;
}

}  // namespace fooball::bullet_detail
