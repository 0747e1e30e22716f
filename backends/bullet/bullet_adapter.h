#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "ball_bodies.h"
#include "bullet_options.h"
#include "bullet_world.h"
#include "contact_counter.h"
#include "fooball/backend.h"
#include "wall_planes.h"

namespace fooball::bullet_detail {

/// The Backend on Bullet 3.24 (Debian's libbullet-dev, single precision): balls are dynamic
/// spheres held to the plane z = 0, walls static planes, everything perfectly elastic and
/// frictionless, as a Bullet user who wants restitution 1 sets it up; everything deeper keeps
/// Bullet's default and is an option (bullet_options.h). Bullet's state is float, so positions
/// and velocities are rounded to float on the way in and widened on the way out; the scene's
/// masses are kept beside it in double. Bullet's traps are handled or exposed where they bite:
/// restitution product, friction and restitution threshold in elastic_material.h, the plane,
/// rotation and sleeping in ball_bodies.h, balls a step carries past a wall in
/// wall_containment.h, damping in linear_damping.h, the pools that would
/// allocate per step in bullet_world.h, the process-wide contact callback in contact_counter.h,
/// and the three solver knobs that change the energy at restitution 1 in split_impulse.h,
/// contact_processing.h and warm_starting.h.
class BulletAdapter final : public Backend {
 public:
  BulletAdapter();

  void load(const Scene& scene) override;
  void setWorld(const WorldSettings& world) override;
  void step(double dt, std::span<const Vec2> forces) override;
  void setBall(std::size_t index, const BallDef& ball) override;
  std::size_t ballCount() const override { return balls_.size(); }
  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override;
  BackendCounters counters() const override;
  std::vector<Diagnostic> diagnostics() const override;

 protected:
  void optionsChanged() override;

 private:
  /// A new world holding `balls` in the current box and world settings, with the current options.
  void build(std::span<const BallDef> balls);
  /// The balls as they are now (for rebuilding the world).
  std::vector<BallDef> currentBalls() const;
  /// The solver settings of the options, on the world's btContactSolverInfo.
  void applySolverSettings();
  /// Gives every ball velocity the impulse forces[i]·dt (forces in N), before any Bullet step.
  void applyImpulses(double dt, std::span<const Vec2> forces);
  /// J: what the damping of the next Bullet step of `bulletStep` s takes (linear_damping.h).
  double dragLossOfStep(float bulletStep) const;

  BulletSettings settings_;
  ContactCounts contacts_;       ///< the bodies point to it (contact_counter.h)
  std::vector<BallBody> balls_;  ///< scene order; declared before world_, which outlives none
  WallPlanes walls_;
  std::unique_ptr<BulletWorld> world_;  ///< destroyed first: it touches its bodies as it goes
  std::vector<double> masses_;          ///< kg, the scene's (Bullet's float mass differs)

  Box box_;
  WorldSettings worldSettings_;
  float linearDamping_ = 0.0f;  ///< Bullet's d on every ball (linear_damping.h)

  double dragLoss_ = 0.0;               ///< J
  std::uint64_t bulletSteps_ = 0;       ///< stepSimulation calls since load()
  std::uint64_t worldsBuilt_ = 0;       ///< worlds built since load(), the load's included
  std::uint64_t ballsBroughtBack_ = 0;  ///< by WallContainment since load()
};

}  // namespace fooball::bullet_detail
