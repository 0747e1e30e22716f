#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fooball/backend.h"
#include "fooball/interactions.h"
#include "fooball/metrics.h"
#include "fooball/scene.h"

namespace fooball {

/// The backend's part of one Simulation step, handed out by Simulation::beginStep() so it can
/// run on another thread while the driver keeps drawing the simulation. It owns the backend and
/// the tools' forces until Simulation::finishStep() takes them back.
class BackendStep {
 public:
  /// Steps the backend; on any thread, once. A backend that throws fails the step instead (an
  /// engine whose process died, say): failure() says why in one line, and the simulation goes on
  /// from the state before it on a new backend (RunGroup::finishSteps).
  void run();
  Backend& backend() { return *backend_; }
  /// Why the step failed; empty if it ran.
  const std::string& failure() const { return failure_; }

 private:
  friend class Simulation;
  std::unique_ptr<Backend> backend_;
  std::vector<Vec2> forces_;  // N, one per ball
  bool withForces_ = false;
  double dt_ = 0.0;    // s
  double work_ = 0.0;  // J, done by the forces' kick, booked when the step finishes
  std::string failure_;
};

/// Drives one backend at a fixed time step: forces from the interactions, backend switching
/// with nothing lost, counters that survive a switch, and the energy budget. A RunGroup holds
/// one per run; fooball-cli run drives one directly.
class Simulation {
 public:
  /// `scene` must be valid (validateScene).
  Simulation(const Scene& scene, std::unique_ptr<Backend> backend);

  /// Restarts from `scene` at `startTime` (s): counters and the energy budget start again. A
  /// run group that makes its runs start identical mid-run keeps its clock going this way.
  void load(const Scene& scene, double startTime = 0.0);

  /// Continues on `next` from the current state: next.load(scene()). Time, counters and the
  /// budget carry on.
  void setBackend(std::unique_ptr<Backend> next);
  Backend& backend() { return *backend_; }
  const Backend& backend() const { return *backend_; }

  /// The current state as a scene.
  Scene scene() const;
  /// scene() with saved_from: `backendName` (the backend's registry name, which only the caller
  /// knows: the engine knows no backend by name), every option of the backend with its value,
  /// and time(). What File → Save and run --save write. Needs the backend: not while a step is
  /// out (stepping()).
  Scene savedScene(std::string_view backendName) const;
  /// 0xRRGGBB per ball, scene order: drawing only, kept here so backends need not.
  std::span<const std::uint32_t> colours() const { return colors_; }

  /// Gravity changes the potential energy at once; that jump is booked as external work.
  void setWorld(const WorldSettings& world);
  const WorldSettings& world() const { return world_; }
  const Box& box() const { return box_; }

  /// Replaces ball `index` after validating it; the energy change is booked as external work.
  /// Throws BallError (fooball/ball_problem.h) for a ball that breaks a rule of the scene format
  /// here (values, walls, overlap with another ball), SceneError for no such ball; nothing
  /// changes then.
  void setBall(std::size_t index, const BallDef& ball);
  /// Puts `ball` in at scene index `index` (0 to ballCount()), the later balls one index up: an
  /// undone delete. Validated and booked as setBall; time and counters carry on (replaceBalls).
  void insertBall(std::size_t index, const BallDef& ball);

  /// Continues with a different set of balls (the ball-count spinner, deleting a ball): time,
  /// counters and the budget carry on, and the energy the change adds or removes is booked as
  /// external work. `balls` must be valid in this box (validateScene).
  void replaceBalls(std::vector<BallDef> balls);

  /// s, the fixed physics step (> 0); one step per frame at 60 Hz by default.
  double dt() const { return dt_; }
  void setDt(double dt);

  /// One physics step of dt(), paused or not: finishStep(beginStep()) with run() between.
  void step();
  /// A step in three parts, for a driver that steps the backend on another thread and keeps
  /// reading this simulation meanwhile: beginStep() computes the tools' forces and hands out the
  /// backend; BackendStep::run() steps it; finishStep() takes it back and reads the new state.
  /// While a step is out (stepping()), the state, time, counters, metrics and interactions are
  /// those from before it and may be used; nothing that needs the backend may be called.
  BackendStep beginStep();
  void finishStep(BackendStep&& done);
  /// Gives up the step that is out for good and continues from the state before it on `fresh`,
  /// a new backend of the same kind and options, as setBackend() would. The abandoned backend
  /// stays with whoever runs it (ask it to requestStop()).
  void abandonStep(std::unique_ptr<Backend> fresh);
  bool stepping() const { return backend_ == nullptr; }
  /// Runs whole steps for `seconds` of simulated time (rounded to whole steps; none when
  /// `seconds` is not a positive finite number).
  void run(double seconds);

  /// Everything of this simulation a rewind puts back (fooball/run_history.h) apart from the
  /// backend's internals: the balls, box and world, the clock, the counters and the energy
  /// budget. The tools are not part of it: they are what the user holds now.
  struct State {
    Scene scene;
    double dt = 0.0;        ///< s
    double timeBase = 0.0;  ///< s
    std::uint64_t stepsSinceDtChange = 0;
    std::uint64_t steps = 0;
    BackendCounters earlierBackends;
    BackendCounters backendCounters;
    double initialEnergy = 0.0;  ///< J
    double externalWork = 0.0;   ///< J
    /// Bytes it holds, vectors by capacity.
    std::size_t bytes() const;
  };
  State state() const;
  /// Back to `state` on the backend this simulation has, which is loaded from it. The run
  /// continues bit for bit as it did from there when `state` was taken while backendFresh().
  void restore(const State& state);
  /// Whether the backend has not stepped or been edited since it was loaded from this
  /// simulation's state (load, setBackend, replaceBalls, abandonStep, restore): the state now
  /// is all its future depends on, whatever the backend.
  bool backendFresh() const { return backendFresh_; }
  /// The forces (N, one per ball) the last step applied, or empty when it applied none.
  std::span<const Vec2> lastForces() const;
  /// One step with `forces` (N, or empty for none) in place of the tools': a step replayed as it
  /// was taken, its work booked as the tools' would be.
  void replayStep(std::span<const Vec2> forces);

  double time() const { return timeBase_ + static_cast<double>(stepsSinceDtChange_) * dt_; }
  std::uint64_t steps() const { return steps_; }
  std::size_t ballCount() const { return masses_.size(); }

  Interactions interactions;

  std::span<const Vec2> positions() const { return positions_; }
  std::span<const Vec2> velocities() const { return velocities_; }
  std::span<const double> radii() const { return radii_; }
  std::span<const double> masses() const { return masses_; }
  BallsView balls() const { return {positions_, velocities_, radii_, masses_}; }

  /// Counters summed over every backend this run has used.
  BackendCounters counters() const;

  /// All metrics of DESIGN.md; with GeometryChecks::Skip all but maxOverlap and escaped, which
  /// are then 0 (the O(N log N) overlap search is the dearest part at large N).
  Metrics metrics(GeometryChecks geometry = GeometryChecks::Run) const;

 private:
  void adoptScene(const Scene& scene);
  /// Throws BallError when `ball` may not be in this box among the other balls (all but
  /// `replacing`); `where` names it in what(), e.g. "balls[3]".
  void checkPlacement(const BallDef& ball, std::optional<std::size_t> replacing,
                      std::string_view where) const;
  void refreshState();
  double totalEnergy() const;
  /// Hands the backend out for a step, with forces_ when `withForces`.
  BackendStep handOut(bool withForces);

  std::unique_ptr<Backend> backend_;
  Box box_;
  WorldSettings world_;
  std::vector<Vec2> positions_;
  std::vector<Vec2> velocities_;
  std::vector<double> radii_;
  std::vector<double> masses_;
  std::vector<std::uint32_t> colors_;
  std::vector<Vec2> forces_;
  std::string name_;
  double dt_ = kDefaultDt;
  /// Simulated time is timeBase_ + stepsSinceDtChange_·dt_: exact multiples of dt, no drift from
  /// summing dt step by step.
  double timeBase_ = 0.0;
  std::uint64_t stepsSinceDtChange_ = 0;
  std::uint64_t steps_ = 0;
  BackendCounters earlierBackends_;  ///< counters of backends switched away from
  BackendCounters backendCounters_;  ///< the backend's own, as of the last refreshState()
  double initialEnergy_ = 0.0;
  double externalWork_ = 0.0;  ///< J, by tools, edits and gravity changes
  bool backendFresh_ = true;
  bool lastStepForced_ = false;
};

}  // namespace fooball
