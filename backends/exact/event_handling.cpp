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
  BallMotion& a = balls_[first];
  BallMotion& b = balls_[second];
  const Vec2 separation = b.position - a.position;
  const double distance = std::sqrt(lengthSquared(separation));  // no overflow at box scales
  if (distance > 0.0) {
    const Vec2 normal = separation / distance;
    const double approach = dot(b.velocity - a.velocity, normal);
    if (approach < 0.0) {
      // Δv_a = 2·m_b/(m_a + m_b)·u_n·n and the mirror image: each weight is its own quotient
      // (never 1 − the other), so the light ball's change keeps full precision and the heavy
      // one's is tiny but exact, at any mass ratio.
      const double totalMass = mass_[first] + mass_[second];
      a.velocity += (2.0 * approach * (mass_[second] / totalMass)) * normal;
      b.velocity -= (2.0 * approach * (mass_[first] / totalMass)) * normal;
      ++counters_.ballCollisions;
      ++statistics_.collisionsThisStep;
    }
  }
  ++a.version;
  ++b.version;
  liftIfMoving(first);
  liftIfMoving(second);
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
    layToRest(ball, wall);
  } else if (approachSpeed > 0.0) {
    counters_.wallImpulse += 2.0 * mass * approachSpeed;
    counters_.wallCollisions += touchWall(ball, wall);
    normalVelocity = -normalVelocity;
  }
  ++balls_[ball].version;
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

void EventDrivenWorld::liftIfMoving(std::uint32_t ball) {
  if (restingCount_ == 0 || restingOn_[ball] == 0) return;
  for (int axis = 0; axis < 2; ++axis) {
    if (component(balls_[ball].velocity, axis) != 0.0) {
      restingOn_[ball] = static_cast<std::uint8_t>(restingOn_[ball] & ~axisSideBits(axis));
    }
  }
  if (restingOn_[ball] == 0) --restingCount_;
}

}  // namespace fooball::exact
