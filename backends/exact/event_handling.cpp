#include <algorithm>
#include <cmath>

#include "event_driven_world.h"
#include "free_flight.h"

namespace fooball::exact {

void EventDrivenWorld::advance(std::uint32_t ball, double time) {
  BallMotion& motion = balls_[ball];
  const double tau = time - motion.time;
  if (!(tau > 0.0)) return;
  const FlightFactors flight = flightFactors(world_.airResistance, tau);
  const Vec2 gravity = gravityOf(ball);
  const Vec2 velocity = motion.velocity;
  const Vec2 displacement = flightDisplacement(velocity, gravity, flight);
  const Vec2 newVelocity = flightVelocity(velocity, gravity, flight);
  const double mass = mass_[ball];
  if (world_.airResistance > 0.0) {
    // Drag is the only force doing work in free flight, so what it took is −(ΔKE + ΔPE);
    // ΔKE as ½m(v1 − v0)·(v1 + v0) and ΔPE from the displacement keep it free of cancellation.
    const double kineticChange = 0.5 * mass * dot(newVelocity - velocity, newVelocity + velocity);
    const double potentialChange = -mass * dot(world_.gravity, displacement);
    counters_.dragLoss -= kineticChange + potentialChange;
  }
  if (restingCount_ != 0 && restingOn_[ball] != 0) {  // walls carry m·|g_n| for τ
    const Vec2 carried = world_.gravity - gravity;
    counters_.wallImpulse += mass * (std::abs(carried.x) + std::abs(carried.y)) * tau;
  }
  motion.position += displacement;
  motion.velocity = newVelocity;
  motion.time = time;
}

void EventDrivenWorld::handle(std::uint32_t ball, const Event& interaction) {
  switch (interaction.kind) {
    case EventKind::Pair:
      if (balls_[interaction.target].version == interaction.partnerVersion) {
        collide(ball, interaction.target);
      } else {
        predict(ball);  // the partner changed course since: look again from now
      }
      return;
    case EventKind::Wall:
      bounce(ball, static_cast<Side>(interaction.target));
      return;
    case EventKind::Recheck:
    case EventKind::None:
      predict(ball);
      return;
  }
}

void EventDrivenWorld::collide(std::uint32_t first, std::uint32_t second) {
  advance(first, now_);
  advance(second, now_);
  releaseWalls(first);
  releaseWalls(second);
  if (asleep(first) || asleep(second)) {
    if (asleep(first)) {
      meetSleeper(second, first);
    } else {
      meetSleeper(first, second);
    }
    return;
  }
  exchange(first, second);
  ++balls_[first].version;
  ++balls_[second].version;
  liftIfMoving(first);
  liftIfMoving(second);
  if (restSpeed_ > 0.0) {
    trySleep(first);
    trySleep(second);
  }
  predict(first);
  predict(second);
}

void EventDrivenWorld::bounce(std::uint32_t ball, Side wall) {
  advance(ball, now_);
  releaseWalls(ball);
  const int axis = axisOf(wall);
  const double inward = isLowerSide(wall) ? 1.0 : -1.0;
  double& normalVelocity = componentRef(balls_[ball].velocity, axis);
  const double approachSpeed = std::max(-inward * normalVelocity, 0.0);
  const double push = -inward * component(world_.gravity, axis);  // m/s² towards the wall
  const double mass = mass_[ball];
  if (push > 0.0 && 2.0 * approachSpeed <= push * limits_.restBounceTime) {
    counters_.wallImpulse += mass * approachSpeed;
    if (approachSpeed > 0.0) counters_.wallCollisions += touchWall(ball, wall);
    const double bound = 0.5 * push * limits_.restBounceTime;  // m/s, the most it drops
    statistics_.restEnergyBound += 0.5 * mass * bound * bound;
    layToRest(ball, wall);
  } else if (approachSpeed > 0.0) {
    counters_.wallImpulse += 2.0 * mass * approachSpeed;
    counters_.wallCollisions += touchWall(ball, wall);
    normalVelocity = -normalVelocity;
  }
  ++balls_[ball].version;
  trySleep(ball);
  predict(ball);
}

void EventDrivenWorld::layToRest(std::uint32_t ball, Side wall) {
  BallMotion& motion = balls_[ball];
  const int axis = axisOf(wall);
  double& coordinate = componentRef(motion.position, axis);
  double& normalVelocity = componentRef(motion.velocity, axis);
  const double contact = contactCoordinate(wall, motion.radius);
  const double mass = mass_[ball];
  statistics_.restEnergyChange += -0.5 * mass * normalVelocity * normalVelocity -
                                  mass * component(world_.gravity, axis) * (contact - coordinate);
  coordinate = contact;
  normalVelocity = 0.0;
  if (restingOn_[ball] == 0) ++restingCount_;
  restingOn_[ball] |= sideBit(wall);
}

/// After a collision or a force: a ball no longer rests on a wall along an axis it now moves
/// along, and a sleeping ball that moves wakes (with the sleepers it alone held).
void EventDrivenWorld::liftIfMoving(std::uint32_t ball) {
  if (restingCount_ == 0 || restingOn_[ball] == 0) return;
  std::uint8_t restingOn = restingOn_[ball];
  for (int axis = 0; axis < 2; ++axis) {
    if (component(balls_[ball].velocity, axis) != 0.0)
      restingOn = static_cast<std::uint8_t>(restingOn & ~axisSideBits(axis));
  }
  setRestBits(ball, restingOn);
  if ((restingOn & kAsleep) == 0 || balls_[ball].velocity == Vec2{}) return;
  if (calendarValid_) {
    wake(ball);
  } else {  // the rebuild to come wakes every ball
    setRestBits(ball, static_cast<std::uint8_t>(restingOn & ~kAsleep));
  }
}

}  // namespace fooball::exact
