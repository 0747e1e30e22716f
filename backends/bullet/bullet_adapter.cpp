#include "bullet_adapter.h"

#include "collision_filter.h"
#include "elastic_material.h"
#include "linear_damping.h"
#include "plane_vectors.h"

namespace fooball::bullet_detail {

BulletAdapter::BulletAdapter() : Backend(bulletOptionSpecs()) {
  installContactCounter();
  settings_ = readBulletSettings(options_);
  build({});
}

void BulletAdapter::load(const Scene& scene) {
  box_ = scene.box;
  worldSettings_ = scene.world;
  linearDamping_ = bulletLinearDamping(worldSettings_.airResistance);
  worldsBuilt_ = 0;
  contacts_ = {};
  build(scene.balls);
  dragLoss_ = 0.0;
  bulletSteps_ = 0;
  ballsBroughtBack_ = 0;
}

void BulletAdapter::build(std::span<const BallDef> balls) {
  world_.reset();  // first: it removes its bodies' proxies as it goes
  walls_.forget();
  balls_.clear();
  world_ = std::make_unique<BulletWorld>(balls.size());
  btDiscreteDynamicsWorld& world = world_->get();
  world.setGravity(toBullet(worldSettings_.gravity));
  applySolverSettings();
  const auto threshold = static_cast<float>(settings_.contactProcessingThreshold);
  walls_.sync(world, box_, worldSettings_.walls, threshold, &contacts_);

  masses_.resize(balls.size());
  balls_.reserve(balls.size());
  const BallSetup setup{linearDamping_, threshold, &contacts_};
  contacts_.touches.assign(balls.size(), 0);  // a new world: contacts begin anew
  const int mask = ballMask(worldSettings_.ballCollisions);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    masses_[i] = balls[i].mass;
    balls_.push_back(createBall(balls[i], i, setup));
    world.addRigidBody(balls_.back().body.get(), kBallGroup, mask);
  }
  ++worldsBuilt_;
}

void BulletAdapter::applySolverSettings() {
  btContactSolverInfo& info = world_->get().getSolverInfo();
  removeRestitutionThreshold(info);
  info.m_numIterations = settings_.solverIterations;
  info.m_splitImpulsePenetrationThreshold =
      static_cast<float>(settings_.splitImpulsePenetrationThreshold);
  info.m_warmstartingFactor = static_cast<float>(settings_.warmStarting);
}

std::vector<BallDef> BulletAdapter::currentBalls() const {
  std::vector<BallDef> balls(balls_.size());
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const btRigidBody& body = *balls_[i].body;
    balls[i].position = fromBullet(body.getWorldTransform().getOrigin());
    balls[i].velocity = fromBullet(body.getLinearVelocity());
    balls[i].radius = static_cast<double>(balls_[i].shape->getRadius());
    balls[i].mass = masses_[i];
  }
  return balls;
}

void BulletAdapter::setWorld(const WorldSettings& world) {
  const bool rebuild = world.ballCollisions != worldSettings_.ballCollisions;
  worldSettings_ = world;
  linearDamping_ = bulletLinearDamping(world.airResistance);
  if (rebuild) {
    // The collision filter is read when a pair is made (collision_filter.h): a new world.
    build(currentBalls());
    return;
  }
  btDiscreteDynamicsWorld& bulletWorld = world_->get();
  bulletWorld.setGravity(toBullet(world.gravity));  // every ball's gravity force too
  for (BallBody& ball : balls_)
    ball.body->setDamping(linearDamping_, 0.0f);
  walls_.sync(bulletWorld, box_, world.walls,
              static_cast<float>(settings_.contactProcessingThreshold), &contacts_);
}

void BulletAdapter::setBall(std::size_t index, const BallDef& ball) {
  BallBody& edited = balls_[index];
  btDiscreteDynamicsWorld& world = world_->get();
  setBallShape(edited, ball.radius, ball.mass, world.getGravity());
  btTransform transform;
  transform.setIdentity();
  transform.setOrigin(toBullet(ball.position));
  edited.body->setWorldTransform(transform);
  edited.body->setInterpolationWorldTransform(transform);
  edited.body->setLinearVelocity(toBullet(ball.velocity));
  masses_[index] = ball.mass;
  contacts_.touches[index] = 0;  // an edited ball begins its contacts anew
  world.updateSingleAabb(edited.body.get());
  // Its contact points were found for where it was, with its old radius: dropped, so the next
  // step finds its contacts afresh.
  world.getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
      edited.body->getBroadphaseHandle(), world.getDispatcher());
}

void BulletAdapter::readState(std::span<Vec2> positions, std::span<Vec2> velocities) const {
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const btRigidBody& body = *balls_[i].body;
    positions[i] = fromBullet(body.getWorldTransform().getOrigin());
    velocities[i] = fromBullet(body.getLinearVelocity());
  }
}

BackendCounters BulletAdapter::counters() const {
  return {contacts_.ballCollisions, contacts_.wallCollisions, contacts_.wallImpulse, dragLoss_};
}

std::vector<Diagnostic> BulletAdapter::diagnostics() const {
  return {
      {"bullet_steps", static_cast<double>(bulletSteps_)},
      {"worlds_built", static_cast<double>(worldsBuilt_)},
      {"balls_brought_back", static_cast<double>(ballsBroughtBack_)},
  };
}

void BulletAdapter::optionsChanged() {
  const double thresholdBefore = settings_.contactProcessingThreshold;
  settings_ = readBulletSettings(options_);
  if (settings_.contactProcessingThreshold != thresholdBefore) {
    // A manifold reads its threshold from its two bodies when it is made (contact_processing.h),
    // and the wall pairs' manifolds last as long as the world: a new world.
    build(currentBalls());
    return;
  }
  applySolverSettings();
}

}  // namespace fooball::bullet_detail
