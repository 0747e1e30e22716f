#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "box2d_options.h"
#include "contact_counter.h"
#include "fooball/backend.h"
#include "velocity_scan.h"
#include "wall_bodies.h"

namespace fooball::box2d_detail {

/// The Backend on Box2D 2.4.1: balls are dynamic circles, walls static thick boxes, everything
/// perfectly elastic and frictionless (elastic_fixture.h). Box2D's state is float, so positions
/// and velocities are rounded to float on the way in and widened on the way out; the scene's
/// masses are kept beside it in double (Box2D's float density·πr² differs by ~1e-7). Box2D's
/// traps are handled where they bite: restitution threshold and friction in
/// elastic_fixture.h, rotation and sleeping in ball_bodies.h, the translation cap in
/// translation_cap.h, damping in linear_damping.h, the polygon skin in wall_bodies.cpp.
class Box2dAdapter final : public Backend {
 public:
  Box2dAdapter();

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
  /// Gives every ball velocity the impulse forces[i]·dt (forces in N), before any Box2D step.
  void applyImpulses(double dt, std::span<const Vec2> forces);
  /// Sets the ball bodies' damping for a Box2D step of `box2dStep` s if it changed, and returns
  /// the energy (J) that step's damping will take from velocities scanned as `before`.
  double prepareDrag(float box2dStep, const VelocityScan& before);
  void setBallDamping(float linearDamping);

  Box2dSettings settings_;
  ContactCounter contacts_;  ///< declared before world_, which holds a pointer to it
  std::unique_ptr<b2World> world_;
  WallBodies walls_;
  std::vector<b2Body*> balls_;  ///< scene order (Box2D's own body list is in reverse order)
  std::vector<double> masses_;  ///< kg, the scene's (Box2D's float mass differs by ~1e-7)
  double totalMass_ = 0.0;      ///< kg

  Box box_;
  WorldSettings worldSettings_;

  /// The Box2D step (s) the balls' linearDamping was computed for; 0 when it must be redone.
  float dampedStep_ = 0.0f;
  float linearDamping_ = 0.0f;  ///< 1/s, Box2D's coefficient on every ball

  double dragLoss_ = 0.0;                 ///< J
  std::uint64_t translationCapHits_ = 0;  ///< ball-steps ending at the cap speed
  std::uint64_t substepsRaised_ = 0;      ///< step() calls that auto_substeps lengthened
  std::uint64_t box2dSteps_ = 0;          ///< b2World::Step calls since load()
  std::uint64_t ballsPutBack_ = 0;        ///< by WallContainment since load()
};

}  // namespace fooball::box2d_detail
