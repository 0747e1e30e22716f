#include "bare_box2d_world.h"

#include "box2d/ball_bodies.h"
#include "box2d/box2d_options.h"
#include "box2d/seam_contacts.h"

namespace fooball::benchmarks {

BareBox2dWorld::BareBox2dWorld(const Scene& scene)
    : world_(std::make_unique<b2World>(b2Vec2(static_cast<float>(scene.world.gravity.x),
                                              static_cast<float>(scene.world.gravity.y)))) {
  world_->SetAllowSleeping(false);
  world_->SetAutoClearForces(false);  // as the adapter: nothing applies forces to the bodies
  world_->SetContactListener(&seams_);
  walls_.sync(*world_, scene.box, scene.world.walls);
  const box2d_detail::Box2dSettings defaults;
  for (const BallDef& ball : scene.balls)
    box2d_detail::createBallBody(*world_, ball, scene.world.ballCollisions, defaults.bullets);
}

void BareBox2dWorld::SeamListener::PreSolve(b2Contact* contact, const b2Manifold*) {
  box2d_detail::disableWallCornerContact(*contact);
}

void BareBox2dWorld::step(double dt, int substeps) {
  const box2d_detail::Box2dSettings defaults;
  const auto box2dStep = static_cast<float>(dt / substeps);
  for (int substep = 0; substep < substeps; ++substep)
    world_->Step(box2dStep, defaults.velocityIterations, defaults.positionIterations);
}

}  // namespace fooball::benchmarks
