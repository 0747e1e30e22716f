#include "xpbd_world.h"

#include <algorithm>
#include <cmath>

#include "common/exact_size.h"

namespace fooball::xpbd {

namespace {

/// Sorts the balls' slots by the cell of their current centres, numbered from the lower left,
/// by one worker.
void sortByCell(common::CellLists& grid, std::span<const Particle> particles) {
  constexpr auto kOrder = common::CellOrder::FromLowerLeft;
  for (std::size_t slot = 0; slot < particles.size(); ++slot) {
    const Particle& p = particles[slot];
    grid.setCell(slot, grid.cellOf(p.x, p.y, p.radius, kOrder));
  }
  grid.countShare(0);
  grid.sortShare(0, kOrder);
}

}  // namespace

void XpbdWorld::load(std::span<const BallDef> balls, const Box& box, const WorldSettings& world) {
  box_ = box;
  world_ = world;
  particles_.assign(balls);
  counters_ = {};
  substepCount_ = 0;
  layout();
}

void XpbdWorld::setBall(std::size_t slot, const BallDef& ball) {
  particles_.set(slot, ball);
  layout();
}

void XpbdWorld::layout() {
  const std::size_t balls = particles_.size();
  grid_.layout(balls, box_.width, box_.height,
               2.0 * common::gridRadius<Particle>(particles_.particle, kBallsPerOversized), 1);
  memory_.reset(balls);
  // Room for a contact per ball and for a quarter of the balls on a wall, so that an ordinary
  // scene's steady state does not allocate; piles and crowds grow the buffers once, in their
  // first steps (32 and 40 bytes per entry: a contact per ball costs half the balls' own memory).
  pairs_.reserve(balls + 64);
  wallContacts_.reserve(balls / 4 + 64);
  common::resizeExactly(wallRecordOf_, 2 * balls);
}

void XpbdWorld::step(double dt, std::span<const Vec2> forces) {
  if (!forces.empty()) {
    for (std::size_t slot = 0; slot < particles_.size(); ++slot) {
      const Vec2 force = forces[particles_.id[slot]];
      Particle& p = particles_.particle[slot];
      p.vx += force.x * dt / p.mass;
      p.vy += force.y * dt / p.mass;
    }
  }
  // A step of no time moves nothing, and v = (x − x_prev)/h would divide by zero.
  if (!(dt > 0.0)) return;
  const double h = dt / substeps_;
  for (int s = 0; s < substeps_; ++s)
    substep(h);
}

void XpbdWorld::predict(double h) {
  const double gx = world_.gravity.x * h;
  const double gy = world_.gravity.y * h;
  const bool drag = world_.airResistance > 0.0;
  // Exact decay of dv/dt = −c·v over h; the kinetic energy it takes is booked as drag loss.
  const double decay = drag ? std::exp(-world_.airResistance * h) : 1.0;
  double dragLoss = 0.0;
  for (std::size_t slot = 0; slot < particles_.size(); ++slot) {
    Particle& p = particles_.particle[slot];
    p.xPrev = p.x;
    p.yPrev = p.y;
    if (drag) {
      const double speedSquared = p.vx * p.vx + p.vy * p.vy;
      p.vx *= decay;
      p.vy *= decay;
      dragLoss += 0.5 * p.mass * (speedSquared - (p.vx * p.vx + p.vy * p.vy));
    }
    p.vx += gx;
    p.vy += gy;
    p.x += h * p.vx;
    p.y += h * p.vy;
    particles_.moved[slot] = 0;
  }
  counters_.dragLoss += dragLoss;
}

void XpbdWorld::deriveVelocities(double h) {
  const double inverseH = 1.0 / h;
  for (std::size_t slot = 0; slot < particles_.size(); ++slot) {
    if (particles_.moved[slot] == 0) continue;
    Particle& p = particles_.particle[slot];
    p.vx = (p.x - p.xPrev) * inverseH;
    p.vy = (p.y - p.yPrev) * inverseH;
  }
}

void XpbdWorld::substep(double h) {
  const WallContacts walls(box_, world_.walls);
  walls.release(particles_);
  predict(h);
  const bool collisions = world_.ballCollisions && particles_.size() > 1;
  if (collisions) {
    sortByCell(grid_, particles_.particle);
    if (substepCount_ % kSubstepsPerReorder == 0) {
      // Move the balls into cell order: the sorted slots become the identity, and the grid
      // still describes the balls, now in their new slots.
      particles_.permute(grid_.sortedSlots());
    }
    pairs_.find(particles_.particle, grid_);
  } else {
    pairs_.clear();
  }
  wallContacts_.clear();
  for (int iteration = 0; iteration < iterations_; ++iteration) {
    if (pairs_.size() > 0) pairs_.project(particles_);
    counters_.wallCollisions += walls.project(particles_, wallContacts_, wallRecordOf_);
  }
  deriveVelocities(h);
  for (int iteration = 0; iteration < iterations_; ++iteration) {
    if (pairs_.size() > 0) pairs_.restitute(particles_);
    restituteWalls(particles_, wallContacts_);
  }
  if (pairs_.size() > 0)
    counters_.ballCollisions += pairs_.countEvents(particles_, memory_, substepCount_);
  memory_.commit(substepCount_);
  counters_.wallImpulse += wallImpulse(particles_, wallContacts_, h);
  ++substepCount_;
}

std::size_t XpbdWorld::memoryBytes() const {
  return particles_.memoryBytes() + grid_.memoryBytes() + pairs_.memoryBytes() +
         memory_.memoryBytes() + wallContacts_.capacity() * sizeof(WallContact) +
         wallRecordOf_.capacity() * sizeof(std::uint32_t);
}

}  // namespace fooball::xpbd
