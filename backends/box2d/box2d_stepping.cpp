// The step loop of Box2dAdapter: impulses, auto_substeps against the translation cap, drag
// accounting, and the Box2D steps themselves.

#include <limits>

#include "box2d_adapter.h"
#include "linear_damping.h"
#include "translation_cap.h"

namespace fooball::box2d_detail {

void Box2dAdapter::step(double dt, std::span<const Vec2> forces) {
  if (!forces.empty()) applyImpulses(dt, forces);

  const double gravity = length(worldSettings_.gravity);
  const MassSums sums = worldSettings_.airResistance > 0.0 ? MassSums::kCompute : MassSums::kSkip;
  VelocityScan velocities =
      scanVelocities(balls_, masses_, std::numeric_limits<double>::infinity(), sums);
  int stepsLeft = settings_.substeps;
  int stepsTaken = 0;
  double timeLeft = dt;  // s
  float box2dStep = static_cast<float>(dt / stepsLeft);
  bool raised = false;
  // Box2D's continuous collision can give up and leave a ball deep in a wall, or beyond it
  // (wall_containment.h): it goes back after every Box2D step, before the next or anyone reads it.
  WallContainment walls(box_, worldSettings_.walls);
  while (stepsLeft > 0 && !stopRequested()) {
    // Replanned before every Box2D step, since collisions in the last one may have sped a ball
    // up. The Box2D step stays constant otherwise: Box2D's warm starting prefers that.
    if (settings_.autoSubsteps) {
      const int needed = box2dStepsBelowCap(velocities.fastestSpeed, gravity, timeLeft,
                                            kMaxBox2dStepsPerStep - stepsTaken);
      if (needed > stepsLeft) {
        stepsLeft = needed;
        box2dStep = static_cast<float>(timeLeft / stepsLeft);
        raised = true;
      }
    }
    if (worldSettings_.airResistance > 0.0) dragLoss_ += prepareDrag(box2dStep, velocities);

    world_->Step(box2dStep, settings_.velocityIterations, settings_.positionIterations);
    contacts_.releaseWalls(balls_, box_);
    velocities =
        scanVelocities(balls_, masses_, capSpeed(static_cast<double>(box2dStep)), sums, &walls);
    translationCapHits_ += velocities.ballsAtCap;
    timeLeft -= static_cast<double>(box2dStep);
    --stepsLeft;
    ++stepsTaken;
  }
  box2dSteps_ += static_cast<std::uint64_t>(stepsTaken);
  ballsPutBack_ += walls.ballsPutBack();
  contacts_.wallImpulse += walls.impulse();
  if (raised) ++substepsRaised_;
}

void Box2dAdapter::applyImpulses(double dt, std::span<const Vec2> forces) {
  // Velocity is set directly, not through b2Body::ApplyLinearImpulse, so the change is
  // forces[i]·dt / m with the scene's mass, exactly as the driver books the work.
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const b2Vec2 v = balls_[i]->GetLinearVelocity();
    const Vec2 velocity =
        Vec2{static_cast<double>(v.x), static_cast<double>(v.y)} + forces[i] * (dt / masses_[i]);
    balls_[i]->SetLinearVelocity({static_cast<float>(velocity.x), static_cast<float>(velocity.y)});
  }
}

double Box2dAdapter::prepareDrag(float box2dStep, const VelocityScan& before) {
  if (box2dStep != dampedStep_) {
    setBallDamping(box2dLinearDamping(worldSettings_.airResistance, box2dStep));
    dampedStep_ = box2dStep;
  }
  const b2Vec2 gravity = world_->GetGravity();  // the float gravity Box2D integrates with
  return dampingLoss(before, totalMass_,
                     {static_cast<double>(gravity.x), static_cast<double>(gravity.y)},
                     static_cast<double>(box2dStep),
                     static_cast<double>(box2dDampingFactor(linearDamping_, box2dStep)));
}

}  // namespace fooball::box2d_detail
