// The step loop of ChipmunkAdapter: impulses, then per Chipmunk step the gravity and drag kick
// (flight.h), cpSpaceStep, and the wall containment (wall_containment.h).
//
// Debian's Chipmunk keeps its assertions (built without NDEBUG): a failed cpAssertSoft or
// cpAssertHard prints "Aborting due to Chipmunk error" and calls abort(), killing the GUI or a
// whole test binary. What the library checks, and why none of it can fail here:
// - every body set or integrated must have finite position and velocity and a non-NaN mass and
//   moment (cpBodySanityCheck, also at the end of every cpBodyUpdatePosition/Velocity): the
//   adapter hands it only validated scene values (validateScene/validateBall: finite, positive,
//   bounded sizes), kicks of finite forces and gravity over finite steps, and the infinite
//   moment, which is not NaN (ball_bodies.h);
// - mass in [0, ∞), moment ≥ 0, elasticity and friction ≥ 0, iterations > 0, damping ≥ 0: the
//   scene's masses, ∞, 1, 0 (elastic_material.h), the option's minimum of 1, and 1;
// - a contact's effective mass must not be 0 ("Unsolvable collision"): 1/m_a + 1/m_b > 0 for
//   every finite mass, and walls are static;
// - no shape or body is added or removed while the space is locked: the collision handlers
//   (contact_counter.h) only count;
// - the spatial hash's table stays below 1.6e9 cells (broadphase.h caps it at 2^24).
// The options' ranges (chipmunk_options.cpp) keep every knob inside what Chipmunk accepts, so
// the random invariants (tests/robustness), which set every option anywhere in its range, throw
// nothing at Chipmunk that it aborts on.

#include <cmath>

#include "broadphase.h"
#include "chipmunk_adapter.h"
#include "flight.h"
#include "wall_containment.h"

namespace fooball::chipmunk_detail {

void ChipmunkAdapter::step(double dt, std::span<const Vec2> forces) {
  if (!forces.empty()) applyImpulses(dt, forces);
  const double h = dt / settings_.substeps;  // s, one Chipmunk step
  const bool kick = worldSettings_.gravity != Vec2{} || worldSettings_.airResistance > 0.0;
  const Walls& on = worldSettings_.walls;
  const bool anyWall = on.left || on.right || on.bottom || on.top;
  WallContainment walls(box_, on, worldSettings_.gravity, wallThickness_);
  int stepsTaken = 0;
  while (stepsTaken < settings_.substeps && !stopRequested()) {
    if (hashCell_ > 0.0) leaveHashIfFar();
    if (kick) {
      dragLoss_ +=
          kickVelocities(bodies_, masses_, worldSettings_.gravity, worldSettings_.airResistance, h);
    }
    cpSpaceStep(space_->get(), h);
    if (anyWall) {
      for (std::size_t i = 0; i < bodies_.size(); ++i)
        walls.contain(bodies_[i], radii_[i], masses_[i], contacts_.touches[i]);
    }
    ++stepsTaken;
  }
  chipmunkSteps_ += static_cast<std::uint64_t>(stepsTaken);
  ballsBroughtBack_ += walls.ballsBroughtBack();
  contacts_.wallCollisions += walls.wallCollisions();
  contacts_.wallImpulse += walls.impulse();
}

bool ChipmunkAdapter::leaveHashIfFar() {
  const double limit = hashSafeCoordinate(hashCell_);  // m
  for (cpBody* body : bodies_) {
    const cpVect p = cpBodyGetPosition(body);
    if (std::abs(p.x) < limit && std::abs(p.y) < limit) continue;
    hashLeft_ = true;
    ++hashesLeft_;
    build(currentBalls());
    return true;
  }
  return false;
}

void ChipmunkAdapter::applyImpulses(double dt, std::span<const Vec2> forces) {
  // Velocity is set directly, not through cpBodyApplyImpulseAtWorldPoint, so the change is
  // forces[i]·dt / m with the scene's mass, exactly as the driver books the work.
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Vec2 kick = forces[i] * (dt / masses_[i]);
    cpBodySetVelocity(bodies_[i], cpvadd(cpBodyGetVelocity(bodies_[i]), cpv(kick.x, kick.y)));
  }
}

}  // namespace fooball::chipmunk_detail
