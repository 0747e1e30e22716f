#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "ball_bodies.h"
#include "chipmunk_options.h"
#include "chipmunk_space.h"
#include "contact_counter.h"
#include "fooball/backend.h"
#include "wall_segments.h"

namespace fooball::chipmunk_detail {

/// The Backend on Chipmunk2D 7.0.3 (Debian's libchipmunk-dev, built with double cpFloat, so the
/// state is the scene's doubles bit for bit): balls are dynamic circles with infinite moment,
/// walls static segments, everything perfectly elastic and frictionless. Chipmunk's traps are
/// handled where they bite: the product of elasticities and friction in elastic_material.h,
/// rotation and sleeping in ball_bodies.h, the order of its integration and its damping in
/// flight.h, its pixel-sized slop and its position bias in contact_slop.h, the missing
/// continuous collision in wall_segments.h and wall_containment.h, the banner Debian's build
/// prints in chipmunk_banner.h and the assertions that abort in chipmunk_stepping.cpp.
class ChipmunkAdapter final : public Backend {
 public:
  ChipmunkAdapter();

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
  /// A new space holding `balls` in the current box and world, with the current options.
  void build(std::span<const BallDef> balls);
  /// The balls as they are now (for rebuilding the space when the broad phase changes).
  std::vector<BallDef> currentBalls() const;
  /// m: the walls' thickness (wall_segments.h), from the radii and the broad phase.
  double chooseWallThickness() const;
  /// Gives every ball velocity the impulse forces[i]·dt (forces in N), before any Chipmunk step.
  void applyImpulses(double dt, std::span<const Vec2> forces);
  /// Moves the space from the spatial hash to the BB-tree if a ball has gone beyond the hash's
  /// safe coordinates (broadphase.h). Returns whether it did.
  bool leaveHashIfFar();

  ChipmunkSettings settings_;
  ContactCounts contacts_;  ///< declared before space_, whose handlers point to it
  std::unique_ptr<Space> space_;
  WallSegments walls_;
  std::vector<BallBody> balls_;  ///< scene order
  std::vector<cpBody*> bodies_;  ///< balls_[i].body, for the passes over the bodies
  std::vector<double> masses_;   ///< kg, the scene's
  std::vector<double> radii_;    ///< m

  Box box_;
  WorldSettings worldSettings_;

  double dragLoss_ = 0.0;               ///< J
  std::uint64_t chipmunkSteps_ = 0;     ///< cpSpaceStep calls since load()
  std::uint64_t ballsBroughtBack_ = 0;  ///< by WallContainment since load()
  std::uint64_t hashesLeft_ = 0;        ///< spaces moved off the spatial hash since load()
  double hashCell_ = 0.0;               ///< m, the spatial hash's cell (0: BB-tree)
  bool hashLeft_ = false;       ///< a ball went too far for the hash: the BB-tree until load()
  double wallThickness_ = 0.0;  ///< m, chosen when the space is built
};

}  // namespace fooball::chipmunk_detail
