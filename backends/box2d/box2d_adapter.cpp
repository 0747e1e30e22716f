#include "box2d_adapter.h"

#include "ball_bodies.h"

namespace fooball::box2d_detail {

namespace {

b2Vec2 toBox2d(Vec2 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y)};
}

Vec2 fromBox2d(b2Vec2 v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

}  // namespace

Box2dAdapter::Box2dAdapter()
    : Backend(box2dOptionSpecs()), world_(std::make_unique<b2World>(b2Vec2(0.0f, 0.0f))) {
  settings_ = readBox2dSettings(options_);
}

void Box2dAdapter::load(const Scene& scene) {
  walls_.forget();
  world_ = std::make_unique<b2World>(toBox2d(scene.world.gravity));
  world_->SetAllowSleeping(false);
  // Nothing applies forces to the bodies (impulses set velocities, gravity is the world's), so
  // there is nothing to clear after every Box2D step.
  world_->SetAutoClearForces(false);
  world_->SetContactListener(&contacts_);
  box_ = scene.box;
  worldSettings_ = scene.world;
  walls_.sync(*world_, box_, worldSettings_.walls);

  balls_.clear();
  masses_.clear();
  balls_.reserve(scene.balls.size());
  masses_.reserve(scene.balls.size());
  totalMass_ = 0.0;
  for (const BallDef& ball : scene.balls) {
    balls_.push_back(
        createBallBody(*world_, ball, worldSettings_.ballCollisions, settings_.bullets));
    balls_.back()->GetUserData().pointer = balls_.size() - 1;  // the contact counter's
    masses_.push_back(ball.mass);
    totalMass_ += ball.mass;
  }

  contacts_.reset(balls_.size());
  dampedStep_ = 0.0f;
  linearDamping_ = 0.0f;
  dragLoss_ = 0.0;
  translationCapHits_ = 0;
  substepsRaised_ = 0;
  box2dSteps_ = 0;
  ballsPutBack_ = 0;
}

void Box2dAdapter::setWorld(const WorldSettings& world) {
  world_->SetGravity(toBox2d(world.gravity));
  if (world.airResistance != worldSettings_.airResistance) {
    dampedStep_ = 0.0f;
    if (world.airResistance == 0.0) setBallDamping(0.0f);
  }
  if (world.ballCollisions != worldSettings_.ballCollisions) {
    for (b2Body* ball : balls_)
      setBallCollisions(*ball, world.ballCollisions);
  }
  walls_.sync(*world_, box_, world.walls);
  worldSettings_ = world;
}

void Box2dAdapter::setBall(std::size_t index, const BallDef& ball) {
  b2Body& body = *balls_[index];
  body.SetTransform(toBox2d(ball.position), 0.0f);
  body.SetLinearVelocity(toBox2d(ball.velocity));
  setBallShape(body, ball.radius, ball.mass);
  masses_[index] = ball.mass;
  contacts_.forgetBall(index);
  totalMass_ = 0.0;
  for (const double mass : masses_)
    totalMass_ += mass;
}

void Box2dAdapter::readState(std::span<Vec2> positions, std::span<Vec2> velocities) const {
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    positions[i] = fromBox2d(balls_[i]->GetPosition());
    velocities[i] = fromBox2d(balls_[i]->GetLinearVelocity());
  }
}

BackendCounters Box2dAdapter::counters() const {
  return {contacts_.ballCollisions, contacts_.wallCollisions, contacts_.wallImpulse, dragLoss_};
}

std::vector<Diagnostic> Box2dAdapter::diagnostics() const {
  return {
      {"translation_cap_hits", static_cast<double>(translationCapHits_)},
      {"auto_substeps_raised", static_cast<double>(substepsRaised_)},
      {"box2d_steps", static_cast<double>(box2dSteps_)},
      {"balls_put_back", static_cast<double>(ballsPutBack_)},
  };
}

void Box2dAdapter::optionsChanged() {
  settings_ = readBox2dSettings(options_);
  for (b2Body* ball : balls_)
    ball->SetBullet(settings_.bullets);
}

void Box2dAdapter::setBallDamping(float linearDamping) {
  linearDamping_ = linearDamping;
  for (b2Body* ball : balls_)
    ball->SetLinearDamping(linearDamping);
}

}  // namespace fooball::box2d_detail
