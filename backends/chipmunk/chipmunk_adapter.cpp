#include "chipmunk_adapter.h"

#include <algorithm>
#include <cmath>

#include "broadphase.h"
#include "contact_slop.h"

namespace fooball::chipmunk_detail {

ChipmunkAdapter::ChipmunkAdapter() : Backend(chipmunkOptionSpecs()) {
  settings_ = readChipmunkSettings(options_);
  build({});
}

void ChipmunkAdapter::load(const Scene& scene) {
  box_ = scene.box;
  worldSettings_ = scene.world;
  hashLeft_ = false;
  hashesLeft_ = 0;
  contacts_ = {};
  build(scene.balls);
  dragLoss_ = 0.0;
  chipmunkSteps_ = 0;
  ballsBroughtBack_ = 0;
}

void ChipmunkAdapter::build(std::span<const BallDef> balls) {
  walls_.forget();
  balls_.clear();
  bodies_.clear();
  space_.reset();  // the old space first: its bodies go with it
  space_ = std::make_unique<Space>();
  cpSpace* space = space_->get();
  // Gravity and damping are the adapter's (flight.h): the space flies balls straight.
  cpSpaceSetGravity(space, cpvzero);
  cpSpaceSetDamping(space, 1.0);
  // INFINITY is the default; said here because a sleeping ball would ignore drag and tools.
  cpSpaceSetSleepTimeThreshold(space, INFINITY);
  cpSpaceSetIterations(space, settings_.iterations);
  installContactCounter(space, &contacts_);

  masses_.resize(balls.size());
  radii_.resize(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    masses_[i] = balls[i].mass;
    radii_[i] = balls[i].radius;
  }
  setContactCorrection(space, radii_, settings_.collisionSlop, settings_.collisionBias);
  hashCell_ = 0.0;
  if (settings_.spatialHash && !hashLeft_) {
    const HashSizing sizing = hashSizing(radii_, box_);
    const double limit = hashSafeCoordinate(sizing.cell);  // m
    hashLeft_ = std::any_of(balls.begin(), balls.end(), [limit](const BallDef& ball) {
      return !(std::abs(ball.position.x) < limit && std::abs(ball.position.y) < limit);
    });
    if (hashLeft_) {
      ++hashesLeft_;
    } else {
      useSpatialHash(space, sizing);
      hashCell_ = sizing.cell;
    }
  }
  wallThickness_ = chooseWallThickness();
  walls_.sync(*space_, box_, worldSettings_.walls, wallThickness_);

  balls_.reserve(balls.size());
  bodies_.reserve(balls.size());
  for (const BallDef& ball : balls) {
    balls_.push_back(createBall(*space_, ball, worldSettings_.ballCollisions));
    bodies_.push_back(balls_.back().body);
    // Its index, for the contact counter (contact_counter.h).
    cpBodySetUserData(bodies_.back(), reinterpret_cast<cpDataPointer>(bodies_.size() - 1));
  }
  contacts_.touches.assign(balls.size(), 0);  // a new space: contacts begin anew
}

double ChipmunkAdapter::chooseWallThickness() const {
  double thickness = radii_.empty() ? 0.01 * std::min(box_.width, box_.height)
                                    : *std::max_element(radii_.begin(), radii_.end());
  if (hashCell_ > 0.0) thickness = std::min(thickness, hashCell_);
  return thickness;
}

std::vector<BallDef> ChipmunkAdapter::currentBalls() const {
  std::vector<BallDef> balls(balls_.size());
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const cpVect p = cpBodyGetPosition(bodies_[i]);
    const cpVect v = cpBodyGetVelocity(bodies_[i]);
    balls[i].position = {p.x, p.y};
    balls[i].velocity = {v.x, v.y};
    balls[i].radius = radii_[i];
    balls[i].mass = masses_[i];
  }
  return balls;
}

void ChipmunkAdapter::setWorld(const WorldSettings& world) {
  if (world.ballCollisions != worldSettings_.ballCollisions) {
    for (const BallBody& ball : balls_)
      setBallCollisions(ball, world.ballCollisions);
  }
  walls_.sync(*space_, box_, world.walls, wallThickness_);
  worldSettings_ = world;  // gravity and drag act from the next kick (flight.h)
}

void ChipmunkAdapter::setBall(std::size_t index, const BallDef& ball) {
  if (hashCell_ > 0.0) {
    const double limit = hashSafeCoordinate(hashCell_);  // m
    if (!(std::abs(ball.position.x) < limit && std::abs(ball.position.y) < limit)) {
      // Too far for the spatial hash (broadphase.h): a new space on the BB-tree.
      std::vector<BallDef> balls = currentBalls();
      balls[index] = ball;
      hashLeft_ = true;
      ++hashesLeft_;
      build(balls);
      return;
    }
  }
  const BallBody& body = balls_[index];
  cpBodySetPosition(body.body, cpv(ball.position.x, ball.position.y));
  cpBodySetVelocity(body.body, cpv(ball.velocity.x, ball.velocity.y));
  setBallShape(*space_, body, ball.radius, ball.mass);
  masses_[index] = ball.mass;
  radii_[index] = ball.radius;
  contacts_.touches[index] = 0;  // an edited ball begins its contacts anew
  // The slop is a fraction of the smallest radius, which this ball may have changed.
  setContactCorrection(space_->get(), radii_, settings_.collisionSlop, settings_.collisionBias);
}

void ChipmunkAdapter::readState(std::span<Vec2> positions, std::span<Vec2> velocities) const {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const cpVect p = cpBodyGetPosition(bodies_[i]);
    const cpVect v = cpBodyGetVelocity(bodies_[i]);
    positions[i] = {p.x, p.y};
    velocities[i] = {v.x, v.y};
  }
}

BackendCounters ChipmunkAdapter::counters() const {
  return {contacts_.ballCollisions, contacts_.wallCollisions, contacts_.wallImpulse, dragLoss_};
}

std::vector<Diagnostic> ChipmunkAdapter::diagnostics() const {
  return {
      {"chipmunk_steps", static_cast<double>(chipmunkSteps_)},
      {"balls_brought_back", static_cast<double>(ballsBroughtBack_)},
      {"spatial_hash_left", static_cast<double>(hashesLeft_)},
  };
}

void ChipmunkAdapter::optionsChanged() {
  const bool hashBefore = settings_.spatialHash;
  settings_ = readChipmunkSettings(options_);
  if (settings_.spatialHash != hashBefore) {
    hashLeft_ = false;
    // Chipmunk can switch a space to a hash but has no call back to the tree: a new space.
    const std::vector<BallDef> balls = currentBalls();
    build(balls);
    return;
  }
  cpSpaceSetIterations(space_->get(), settings_.iterations);
  setContactCorrection(space_->get(), radii_, settings_.collisionSlop, settings_.collisionBias);
}

}  // namespace fooball::chipmunk_detail
