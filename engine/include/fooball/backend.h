#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fooball/options.h"
#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball {

/// Cumulative counts since the last load().
struct BackendCounters {
  std::uint64_t ballCollisions = 0;  ///< ball–ball impulses exchanged
  std::uint64_t wallCollisions = 0;  ///< wall bounces
  double wallImpulse = 0.0;          ///< N·s, Σ|Δp| delivered by the walls
  double dragLoss = 0.0;             ///< J, mechanical energy air resistance has removed (≥ 0)
  /// Steps the backend ended early, at a work cap the user set (OptionRole::EventCap) or at a
  /// loop of events at one instant: the rest of each moved without collisions, so the counts
  /// and the physics of those steps are incomplete.
  std::uint64_t cutShortSteps = 0;
  /// J, energy a method's resting rules changed by design, booked as it happened (the exact
  /// solver laying balls to rest on walls and putting balls to sleep on balls, within the bound
  /// its options state); the energy budget takes it out, as it does drag.
  double restEnergyChange = 0.0;
  /// Balls resting now (the exact solver: on a wall or asleep). A state, not a sum: after a
  /// backend switch it is the current backend's.
  std::uint64_t restingBalls = 0;
};

/// A backend-specific reading reported beside the counters, e.g. Box2D's translation-cap hits
/// or the exact solver's event count.
struct Diagnostic {
  std::string name;
  double value = 0.0;
};

/// One physics method simulating one scene. All backends obey the same contract (DESIGN.md,
/// "Backend contract"), proven by tests/conformance_test.cpp (each backend's tolerances are its
/// row in tests/backend_profiles.cpp):
/// - momentum is conserved in ball–ball collisions, walls that are on reflect;
/// - with all walls on, every ball stays inside the box, never NaN;
/// - restitution is 1: any energy loss is a measured defect of the method;
/// - deterministic: the same scene, settings and forces give the same trajectory;
/// - no allocation per step in steady state.
/// Balls keep their scene index for their whole life, whatever order a backend stores them in.
/// A backend holds only what its method needs: the scene itself (name, colours, anything else a
/// user sees) belongs to whoever loaded it, e.g. the Simulation, which reads positions and
/// velocities back with readState. Switching backend is next.load(simulation.scene()).
class Backend {
 public:
  explicit Backend(std::vector<OptionSpec> optionSpecs) : options_(std::move(optionSpecs)) {}
  virtual ~Backend() = default;
  Backend(const Backend&) = delete;
  Backend& operator=(const Backend&) = delete;

  /// Replaces the whole state with `scene` (already validated) and zeroes the counters. The
  /// backend keeps what it simulates (box, world, radii, masses, positions, velocities), not the
  /// scene's name or colours.
  virtual void load(const Scene& scene) = 0;

  /// Changes gravity, drag, collisions or walls from now on; positions and velocities stay.
  virtual void setWorld(const WorldSettings& world) = 0;

  /// Advances by `dt` seconds. `forces` (N, one per ball in scene order, or empty for none) act
  /// as an impulse forces[i]·dt applied at the start of the step, so the work they do is exactly
  /// J·(v + J/2m) for every backend; the driver books it in the energy budget.
  virtual void step(double dt, std::span<const Vec2> forces) = 0;

  /// Replaces ball `index` (already validated), e.g. an edit in the inspector; its colour is
  /// the caller's to keep.
  virtual void setBall(std::size_t index, const BallDef& ball) = 0;

  virtual std::size_t ballCount() const = 0;

  /// Copies the balls' centres (m) and velocities (m/s) into caller-owned arrays of
  /// ballCount() elements, in scene order.
  virtual void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const = 0;

  virtual BackendCounters counters() const = 0;
  virtual std::vector<Diagnostic> diagnostics() const { return {}; }

  /// Named knobs with defaults; set* throws std::invalid_argument naming the problem.
  const OptionSet& options() const { return options_; }
  void setOption(std::string_view name, double value) {
    options_.set(name, value);
    optionsChanged();
  }
  void setOptionFromText(std::string_view assignment) {
    options_.setFromText(assignment);
    optionsChanged();
  }
  /// For tools that must finish (the failure map, the random suite): an OptionRole::EventCap
  /// option left at 0, no cap, is set to kFinishingEventsPerBall.
  void capEventsToFinish() {
    const OptionSpec* cap = options_.withRole(OptionRole::EventCap);
    if (cap != nullptr && options_.value(cap->name) == 0.0)
      setOption(cap->name, kFinishingEventsPerBall);
  }

  /// Asks a step running on another thread to end as soon as it can. Thread-safe. Only for a
  /// step whose result nobody will read: the backend is left mid-step and is only fit to be
  /// destroyed. A backend whose one step can run for seconds (Box2D: up to 1,000 Box2D steps)
  /// checks stopRequested() between its iterations; the others just finish.
  void requestStop() { stopRequested_.store(true, std::memory_order_relaxed); }

 protected:
  /// Called after any option changed; read options_ here rather than in the step loop.
  virtual void optionsChanged() {}
  bool stopRequested() const { return stopRequested_.load(std::memory_order_relaxed); }

  OptionSet options_;

 private:
  std::atomic<bool> stopRequested_ = false;
};

}  // namespace fooball
