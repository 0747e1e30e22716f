#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fooball/ball_problem.h"
#include "fooball/divergence.h"
#include "fooball/run_history.h"
#include "fooball/run_spec.h"
#include "fooball/simulation.h"

namespace fooball {

/// One ball as every run of a RunGroup has it: RunGroup::ballStates.
struct BallStates {
  std::vector<BallDef> states;  ///< one per run in run order, then the baseline's
  bool massChosen = false;      ///< RunGroup::massChosen
};

/// How far every run of a RunGroup is from run 0, all at one moment: what the app's compare
/// readout shows and what `fooball-cli compare` writes as that moment's rows.
struct GroupDivergences {
  double time = 0.0;                    ///< s, the moment every figure is of
  std::vector<Divergence> fromRunZero;  ///< index = run index; [0] is run 0's own (zeros)
  std::optional<Divergence> baseline;   ///< the chaos baseline's, when it runs
};

/// How RunGroup::restoreBall puts a ball back: over the ball at its index, or before it.
enum class BallPlacement { Replace, Insert };

/// 1 to kMaxRuns runs of one scene in lockstep (DESIGN.md, "Runs, run specs and run groups"):
/// the same start state, the same dt, the same tool forces and edits, the same number of steps.
/// Run 0 is the reference every other run's divergence is measured from.
///
/// The group owns what the runs have in common — the loaded scene, world settings, the mouse
/// tools (each run keeps only its own grab target, since its balls are elsewhere), edits and
/// ball-count changes, the ball colours, the real-time clock and the cores — so a front end
/// (the app, fooball-cli compare) only says what the user did. Optionally it keeps a chaos
/// baseline: a hidden copy of run 0 whose balls start kBaselineDisplacement away, in seeded
/// random directions. Its divergence from run 0 shows how fast any difference at all grows in
/// this scene; a method whose divergence follows it is as close as chaos allows.
class RunGroup {
 public:
  static constexpr std::size_t kMaxRuns = 8;
  /// m: how far the baseline's balls start from run 0's. Far below any method's error per step
  /// (elastic's overlap resolution, Box2D's float state at 1e-7 relative), far above rounding
  /// of positions of order 1–100 m (1e-14).
  static constexpr double kBaselineDisplacement = 1e-9;
  static constexpr std::uint64_t kBaselineSeed = 0x5eed;

  /// `scene` must be valid (validateScene). Throws std::invalid_argument naming a bad spec, or
  /// when there are no specs or more than kMaxRuns.
  RunGroup(const Scene& scene, const std::vector<RunSpec>& specs, BackendFactory factory);
  ~RunGroup();
  RunGroup(const RunGroup&) = delete;
  RunGroup& operator=(const RunGroup&) = delete;

  // --- The runs -------------------------------------------------------------------------
  std::size_t runCount() const { return runs_.size(); }
  const Simulation& run(std::size_t index) const { return *runs_.at(index).simulation; }
  /// The run's spec as given, with the options set since (its label is spec().text()).
  const RunSpec& spec(std::size_t index) const { return runs_.at(index).spec; }
  std::vector<std::string> labels() const;

  /// Adds a run of `spec` and restarts every run from run 0's state now, so that all start
  /// identical; time carries on (synchronise()). Throws std::invalid_argument for a bad spec or
  /// a ninth run; nothing changes then.
  void addRun(const RunSpec& spec);
  /// Removes run `index` while another is left; the others carry on (removing run 0 makes run 1
  /// the reference, and the baseline follows it).
  void removeRun(std::size_t index);
  /// Continues run `index` on the backend and options of `spec`, from its own state (time and
  /// counters carry on). Throws std::invalid_argument for a bad spec; nothing changes then.
  void setSpec(std::size_t index, const RunSpec& spec);
  /// Sets one option of run `index`'s backend and records it in its spec. Throws
  /// std::invalid_argument naming the problem.
  void setOption(std::size_t index, std::string_view name, double value);
  /// Restarts every run (and the baseline) from run 0's state now: same balls in every run;
  /// time carries on, counters and energy budgets start again.
  void synchronise();

  /// Options with OptionRole::Threads get `cores` shared among the runs (at least 1 each). The
  /// stepping thread waits for every step anyway, and results are the same for any count.
  void shareCores(int cores);

  // --- Divergence and the chaos baseline --------------------------------------------------
  /// Zero for run 0.
  Divergence divergence(std::size_t index) const;
  /// Starts the baseline from run 0's state now (displaced), or drops it.
  void setBaseline(bool on);
  bool hasBaseline() const { return baseline_ != nullptr; }
  /// nullptr without a baseline.
  const Simulation* baseline() const { return baseline_.get(); }
  std::optional<Divergence> baselineDivergence() const;
  /// Every run's divergence and the baseline's now, with the time they are of.
  GroupDivergences divergences() const;

  // --- The scene ----------------------------------------------------------------------------
  /// The scene Restart and Reset go back to.
  const Scene& loadedScene() const { return loadedScene_; }
  /// Every run starts on `scene` (valid) at t = 0; attractors and the selection go.
  void load(const Scene& scene);
  /// Back to the loaded scene at t = 0, keeping the world settings, attractors and ball count
  /// of now (setBallCount's balls).
  void restart();
  /// Run 0's state as a scene.
  Scene scene() const { return run(0).scene(); }
  /// Run 0's state with saved_from (its spec's backend, every option, the time): what File →
  /// Save writes. Needs the backends: not while steps are out (stepping()).
  Scene savedScene() const { return run(0).savedScene(spec(0).backend); }

  const WorldSettings& world() const { return run(0).world(); }
  void setWorld(const WorldSettings& world);
  std::size_t ballCount() const { return run(0).ballCount(); }
  /// 0xRRGGBB per ball, the same in every run.
  std::span<const std::uint32_t> colours() const { return run(0).colours(); }
  /// Ball `index` as run 0 has it.
  BallDef ball(std::size_t index) const;

  /// Adds balls where there is room in every run (placeNewBalls), or removes the newest.
  /// Throws SceneError when they do not fit; nothing changes then.
  void setBallCount(std::size_t count);
  /// The largest ball count setBallCount() takes now: the balls there and the most new balls
  /// that fit beside every run's (placeNewBalls).
  std::size_t mostBallsThatFit() const;
  /// The size of the balls the last setBallCount() added relative to those there (1: same).
  double newBallScale() const { return newBallScale_; }
  /// Replaces ball `index` in every run, or throws SceneError (BallError for a ball that
  /// breaks a rule in some run) and changes none.
  void setBall(std::size_t index, const BallDef& ball);
  /// setBall as a user's edit (the app's inspector): a new mass marks the ball's mass as chosen;
  /// a new radius with the mass as it was scales the mass with the area (m ∝ r², the areal
  /// density kept) unless the mass was chosen. Returns the ball as set.
  BallDef editBall(std::size_t index, BallDef edited);
  /// Whether the user has set ball `index`'s mass (editBall), so resizing it keeps the mass.
  bool massChosen(std::size_t index) const {
    return index < massChosen_.size() && massChosen_[index];
  }
  void deleteBall(std::size_t index);

  /// Ball `index` of every run, for putting it back later (undo, redo): each run's own state,
  /// since the runs diverge.
  BallStates ballStates(std::size_t index) const;
  /// Why `saved` cannot be put back at `index` in some run (see restoreBall), or nothing.
  std::optional<BallProblem> findRestoreProblem(std::size_t index, const BallStates& saved,
                                                BallPlacement placement) const;
  /// Puts `saved` back at `index`, each run's own state into each run (when runs were added or
  /// removed or the baseline toggled since it was taken, every run gets run 0's): over the ball
  /// there (Replace, undoing an edit) or before it (Insert, undoing a delete). Time, counters
  /// and the energy budget carry on (Simulation::insertBall). Throws BallError when the ball
  /// breaks a rule in some run, e.g. another ball is now in its place; nothing changes then.
  void restoreBall(std::size_t index, const BallStates& saved, BallPlacement placement);

  // --- Mouse tools (the same in every run) -------------------------------------------------
  /// The tool settings and attractors, as every run has them (run 0's object).
  const Interactions& interactions() const { return run(0).interactions; }
  void setMouseMode(MouseMode mode);
  void setScope(Scope scope);
  void setStrength(double strength);
  std::optional<std::size_t> selected() const { return interactions().selected; }
  void setSelected(std::optional<std::size_t> index);
  /// A press picks each run's own target among its own balls.
  void pressTool(Vec2 point);
  void moveTool(Vec2 point);
  void releaseTool(Vec2 point);
  void addAttractor(Vec2 point);
  void clearAttractors();

  // --- Stepping -------------------------------------------------------------------------------
  double time() const { return run(0).time(); }
  std::uint64_t steps() const { return run(0).steps(); }
  double dt() const { return run(0).dt(); }
  void setDt(double dt);

  /// One step of every run and the baseline, one after another on this thread.
  void step();
  /// Whole steps for `seconds` of simulated time (rounded; none unless positive and finite).
  void runFor(double seconds);

  /// The steps of one lockstep step, for a driver that runs them on threads of its own: one per
  /// run, then the baseline's. `steps` is caller-owned so that stepping allocates nothing.
  /// While they are out (stepping()), everything but the backends stays readable.
  void beginSteps(std::vector<BackendStep>& steps);
  /// A step that failed (BackendStep::failure): whose, and why.
  struct StepFailure {
    std::optional<std::size_t> run;  ///< the run's index when the step began; none: the baseline
    std::string label;               ///< the run's spec text, or "baseline"
    std::string message;             ///< the backend's one line
  };
  /// Takes them back, all at once, in the order beginSteps() gave them. A failed step ends its
  /// run and the others go on: the runs that failed are removed and a failed baseline starts
  /// again from run 0. If no run stepped, none is removed: every run and the baseline go back to
  /// the state before the step on new backends of their specs, and the group pauses. Returns the
  /// failures, empty when every step ran.
  std::vector<StepFailure> finishSteps(std::vector<BackendStep>& steps);
  /// Gives the steps that are out up for good: every run continues from the state before them
  /// on a fresh backend of its spec. Whoever runs the old ones should requestStop() them.
  void abandonSteps();
  bool stepping() const { return stepping_; }

  /// Real-time driving: pauses, and turns elapsed real time into whole steps.
  bool paused() const { return paused_; }
  void setPaused(bool paused);
  /// The whole steps `elapsedSeconds`·`timeScale` of real time holds now (none while paused),
  /// at most kMaxStepsPerFramePerTimeScale·timeScale, and at most as many as kSteppingPerFrame
  /// of wall-clock time holds at `secondsPerStep` each (the driver's measure of a step's cost;
  /// 0: unknown); at least 1. A machine that cannot keep up drops the backlog and slows the
  /// simulation down instead of spiralling, and one step a frame then: more would make the
  /// frames rarer, not the simulation faster. The caller runs them (step() or beginSteps()).
  int takeDueSteps(double elapsedSeconds, double timeScale, double secondsPerStep = 0.0);
  /// Fixed-time driving (a recording's frames): the whole steps `simulatedSeconds` holds with
  /// what earlier calls left over, however many and however dear (no cap, no backlog dropped),
  /// so that every frame shows the same simulated time after the last; none while paused. The
  /// fraction of a step left stays pending (pendingTime), as in takeDueSteps.
  int takeStepsFor(double simulatedSeconds);
  /// Forgets time not yet stepped, e.g. after a slow step.
  void dropBacklog() { accumulator_ = 0.0; }
  /// s of simulated time that real time has run past the last step and that no step holds yet:
  /// what takeDueSteps() accumulated minus the steps it handed out (below dt() unless a frame
  /// was cut at the cap; 0 while paused, after pausing and after a dropped backlog). A view
  /// draws the balls this far ahead of their stepped state (driftedPositions), so slow motion
  /// moves every frame though a step is due only every few frames.
  double pendingTime() const { return accumulator_; }
  static constexpr double kMaxStepsPerFramePerTimeScale = 4.0;
  /// s of wall-clock stepping one frame may hold: a frame at 60 frames/s.
  static constexpr double kSteppingPerFrame = 1.0 / 60.0;

  // --- Rewind ---------------------------------------------------------------------------------
  /// Keeps moments to rewind to within `bytes` (RunHistory), starting from now; 0 keeps none,
  /// the default, so a driver that never rewinds (fooball-cli) pays nothing. Every change but a
  /// step or a tool's force (edits, settings, runs, the baseline, loading), and a history grown
  /// past its bound with one anchor left, starts the history afresh from now: every backend
  /// that has stepped since it was loaded is reloaded from its state then, as switching backend
  /// does, so the first moment is one every run can be re-stepped from bit for bit. The same
  /// reload makes a new anchor every RunHistory::stepsPerAnchor() steps.
  void setHistoryBound(std::size_t bytes,
                       std::uint64_t ballStepsPerAnchor = RunHistory::kDefaultBallStepsPerAnchor);
  /// nullptr while no history is kept.
  const RunHistory* history() const { return keepsHistory() ? &history_ : nullptr; }
  /// Puts every run and the baseline back at moment `index` of history(), all together: the
  /// state, clock, counters and energy budget they had then, bit for bit. The moments after it
  /// stay until the next step, which drops them. Not while steps are out.
  void rewindTo(std::size_t index);
  /// Rewinds to the moment before the one the runs are at; nothing at the first. Rewinding
  /// re-steps from the latest anchor before the moment: at most RunHistory::stepsPerAnchor().
  void stepBack();

 private:
  struct Run {
    RunSpec spec;
    std::unique_ptr<Simulation> simulation;
  };

  std::unique_ptr<Backend> makeBackend(const RunSpec& spec) const;
  std::unique_ptr<Simulation> makeSimulation(const Scene& scene, const RunSpec& spec) const;
  /// Where new balls go: every run's balls (and the baseline's) at once, as they differ once
  /// the runs diverge: a set of balls per stepper (stepperCount()).
  Scene newBallRoom() const;
  /// Run 0's state with every ball moved kBaselineDisplacement in a seeded random direction.
  Scene displacedScene() const;
  /// Every run and the baseline, in stepping order.
  template <class Action>
  void forEachSimulation(Action&& action);
  /// The state `saved` has for the simulation `k`-th in stepping order (restoreBall).
  const BallDef& savedState(const BallStates& saved, std::size_t k) const;
  void copyToolsTo(Simulation& simulation) const;
  void applyCores(Backend& backend) const;
  std::size_t stepperCount() const { return runs_.size() + (baseline_ ? 1 : 0); }
  bool keepsHistory() const { return history_.bound() > 0; }
  /// Every run and the baseline, in stepping order, in simulations_.
  std::span<Simulation* const> simulations();
  /// Reloads every backend that has stepped since it was loaded (`all`: every one, as after an
  /// option change) from its simulation's state, making a moment to re-step from.
  void reloadBackends(bool all);
  /// See setHistoryBound(); `reload` reloads even a backend that was just loaded (an option
  /// changed since).
  void restartHistory(bool reload = false);
  void recordHistory();

  BackendFactory factory_;
  Scene loadedScene_;
  std::vector<Run> runs_;
  std::unique_ptr<Simulation> baseline_;
  int cores_ = 1;
  bool stepping_ = false;
  bool paused_ = false;
  double accumulator_ = 0.0;  ///< s of simulated time not yet stepped
  double newBallScale_ = 1.0;
  /// massChosen per ball, scene order. Kept here, not in the app's inspector, because the fact
  /// belongs to a ball and must follow it as indices change (deleteBall, restoreBall,
  /// setBallCount, load), which only the group does; not in BallDef or scene files, because it
  /// records what the user did in this session, not physics.
  std::vector<bool> massChosen_;
  RunHistory history_;
  std::vector<Simulation*> simulations_;  ///< simulations()'s, kept to step without allocating
};

}  // namespace fooball
