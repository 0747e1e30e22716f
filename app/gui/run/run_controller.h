#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "fooball/run_group.h"
#include "run/step_worker.h"

namespace fooball::gui {

/// Wall-clock cost of the physics, for the status bar.
struct StepTiming {
  double millisecondsPerStep = 0.0;  ///< of the last step that finished
  std::uint64_t stepsTaken = 0;      ///< steps since the controller was created
};

/// The window's runs: a RunGroup (engine/, where every run's bookkeeping lives) stepped on
/// threads of its own, with Qt signals. Each run and the chaos baseline has a StepWorker. A step
/// that outlasts the patience (100 ms) is left running and the window goes on drawing the state
/// before it; a later advance() collects it. Anything that changes a backend meanwhile
/// (pausing, editing, world settings, runs) first gives the step up, so the runs continue from
/// the state shown.
class RunController : public QObject {
  Q_OBJECT

 public:
  /// `scene` must be valid; throws std::invalid_argument for a bad spec.
  RunController(const Scene& scene, const std::vector<RunSpec>& specs, QObject* parent = nullptr);
  ~RunController() override;

  /// Everything there is to read: runs, specs, divergence, tools, time.
  const RunGroup& group() const { return group_; }
  int runCount() const { return static_cast<int>(group_.runCount()); }
  bool comparing() const { return runCount() > 1; }
  const Simulation& run(int index) const { return group_.run(std::size_t(index)); }
  QString label(int index) const;
  QStringList labels() const;

  /// A change that needs the backends (world settings): gives up a step in flight, then
  /// applies `change` to the group. Signals nothing.
  template <class Change>
  void change(Change&& apply) {
    settle();
    apply(group_);
  }
  /// The world settings of every run, as `edit` adjusts a copy of today's (as change()).
  template <class Edit>
  void changeWorld(Edit&& edit) {
    WorldSettings world = group_.world();
    edit(world);
    change([&](RunGroup& group) { group.setWorld(world); });
  }
  /// A change of the mouse tools (mode, scope, strength, presses, attractors), which the next
  /// step reads: a step in flight carries on. Signals nothing.
  template <class Change>
  void changeTools(Change&& apply) {
    apply(group_);
  }

  /// Starts every run on `scene` (validated by the caller); attractors and selection go.
  void loadScene(const Scene& scene);
  /// Back to the loaded scene at t = 0, keeping the current world settings and attractors.
  void restart();
  /// Run 0's state with saved_from (RunGroup::savedScene): what File → Save writes. Gives up a
  /// step in flight first, so the file holds the state shown and the runs go on from it.
  Scene savedScene();

  /// Run `index` continues on `spec` from its own state. Throws std::invalid_argument.
  void setRunSpec(int index, const RunSpec& spec);
  void setBackendOption(int index, const QString& name, double value);
  /// Adds a run; every run restarts from run 0's state so that all start identical (the time
  /// carries on: runsRestarted). Throws std::invalid_argument (bad spec, a ninth run).
  void addRun(const RunSpec& spec);
  void removeRun(int index);
  void setBaseline(bool on);

  void setSelected(std::optional<std::size_t> index);
  /// Throws SceneError when the balls do not fit; nothing changes then.
  void setBallCount(std::size_t count);
  /// Replaces one ball in every run; throws SceneError (validation) and keeps the state then.
  void setBall(std::size_t index, const BallDef& ball);
  /// RunGroup::editBall: a user's edit, the mass following the radius unless chosen. Throws
  /// SceneError (BallError for a refused ball) and keeps the state then.
  BallDef editBall(std::size_t index, const BallDef& edited);
  void deleteBall(std::size_t index);
  /// RunGroup::restoreBall (undo and redo); throws BallError and keeps the state then.
  void restoreBall(std::size_t index, const BallStates& saved, BallPlacement placement);

  bool paused() const { return group_.paused(); }
  void setPaused(bool paused);
  /// Real-time driving: runs the whole steps `elapsedSeconds`·`timeScale` holds (none while
  /// paused), the same number in every run. Returns the steps run. `whileFirstStepRuns`, if
  /// set, is called once the first of them is out on the workers and before waiting for it:
  /// the window draws the state before the steps then, on a core the step leaves idle, instead
  /// of after them (drawAhead() carries that state over the steps' time).
  int advance(double elapsedSeconds, double timeScale,
              const std::function<void()>& whileFirstStepRuns = {});
  /// Fixed-time driving (a recording): runs every whole step `simulatedSeconds` holds with
  /// what earlier calls left (RunGroup::takeStepsFor), waiting for each however long it takes,
  /// so the state after it is exactly that much later than before; a step left running in the
  /// background by advance() is waited for first. None while paused. Returns the steps run;
  /// `whileFirstStepRuns` as in advance().
  int advanceExactly(double simulatedSeconds, const std::function<void()>& whileFirstStepRuns = {});
  /// One step of every run, paused or not.
  void stepOnce();
  /// Every run and the baseline back at moment `index` of the group's history (RunGroup::
  /// rewindTo); emits rewound. The app keeps RunHistory::kDefaultBound bytes of history.
  void rewindTo(std::size_t index);
  /// One moment back (RunGroup::stepBack); emits rewound.
  void stepBack();
  StepTiming stepTiming(int index) const { return timing_.at(std::size_t(index)); }
  /// s the last lockstep step took: its slowest worker's, the baseline's included. advance()
  /// takes no more steps a frame than a frame's time holds at this cost (RunGroup::
  /// takeDueSteps).
  double lastStepSeconds() const { return lastStepSeconds_; }

  /// How long advance() and stepOnce() wait for a step before leaving it to run in the
  /// background: long enough for any step that keeps a frame rate, short enough to be a hitch
  /// rather than a freeze.
  static constexpr std::chrono::milliseconds kDefaultStepPatience{100};
  /// For runs that must show every step, however slow (headless measurements, tests): an hour.
  static constexpr std::chrono::milliseconds kWaitForEveryStep = std::chrono::hours(1);
  void setStepPatience(std::chrono::milliseconds patience) { stepPatience_ = patience; }
  /// True while a step runs in the background; the runs show the state before it.
  bool stepping() const { return group_.stepping(); }
  /// s the step still running has taken so far (the slowest run's), 0 when none.
  double stepSeconds() const;
  /// s of simulated time a view draws the balls ahead of the state it shows
  /// (driftedPositions): the time not stepped yet (RunGroup::pendingTime), and during
  /// advance()'s whileFirstStepRuns also the time of the steps it is running.
  double drawAhead() const { return group_.pendingTime() + stepsOut_ * group_.dt(); }

 signals:
  /// A run's backend changed, or runs were added or removed.
  void runsChanged();
  /// An option of run `index` changed (its label with it); its options form stays as it is.
  void optionsChanged(int index);
  /// Every run restarted from run 0's state at simulated time `time` (s), so that they start
  /// identical.
  void runsRestarted(double time);
  /// The set of balls changed: a scene was loaded, balls were added, removed or edited.
  void ballsChanged();
  void pausedChanged(bool paused);
  /// The runs were rewound to simulated time `time` (s).
  void rewound(double time);
  void selectionChanged(std::optional<std::size_t> index);
  /// Runs' steps failed (an engine's process died, say): one line each, "SPEC stopped: WHY".
  /// The runs at `removed` (their indices before, highest first) are gone and the others go on;
  /// if every run failed, none is removed: they are back where the step began, paused
  /// (RunGroup::finishSteps).
  void runsFailed(const QString& lines, const QList<int>& removed);

 private:
  /// Runs `steps` steps of every run, calling `whileFirstStepRuns` (if set) while the first is
  /// out; returns how many finished (the last may still be running).
  int stepRuns(int steps, std::chrono::milliseconds patience,
               const std::function<void()>& whileFirstStepRuns = {});
  /// Finishes the runs' steps if all are done within `patience`; false (nothing finished) if not.
  bool collectSteps(std::chrono::milliseconds patience);
  /// Gives up a step still running (see the class comment), so the backends are here to change.
  void settle();
  /// One worker per run and baseline, one timing per run.
  void matchWorkersToRuns();
  /// After finishSteps() failed some: the timings of the runs it removed go, then the signals.
  void reportFailures(const std::vector<RunGroup::StepFailure>& failures);

  RunGroup group_;
  std::vector<BackendStep> steps_;  ///< the steps out, in RunGroup::beginSteps order
  std::vector<std::unique_ptr<StepWorker>> workers_;
  std::vector<StepTiming> timing_;
  std::chrono::milliseconds stepPatience_ = kDefaultStepPatience;
  int stepsOut_ = 0;  ///< steps of advance() whose time drawAhead() adds: only while drawing
  double lastStepSeconds_ = 0.0;  ///< s, see lastStepSeconds()
};

}  // namespace fooball::gui
