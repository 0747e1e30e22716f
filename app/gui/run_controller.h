#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "fooball/interactions.h"
#include "fooball/scene.h"
#include "fooball/simulation.h"
#include "step_worker.h"

namespace fooball::gui {

/// How far the compare run has drifted from the main run, ball by ball (same scene index).
struct Divergence {
  double rmsPositionDifference = 0.0;     ///< m, √(mean |p_compare − p_main|²)
  double maxPositionDifference = 0.0;     ///< m
  double energyDifference = 0.0;          ///< J, E_compare − E_main
  double relativeEnergyDifference = 0.0;  ///< (E_compare − E_main) / |E_main|, 0 when E_main = 0
  double momentumDifference = 0.0;        ///< N·s, |p_compare − p_main|
};

/// Wall-clock cost of the physics, for the status bar.
struct StepTiming {
  double millisecondsPerStep = 0.0;  ///< of the last step that finished
  std::uint64_t stepsTaken = 0;      ///< steps since the controller was created
};

/// The one or two runs the window shows. Run 0 is the main run; in compare mode run 1 runs the
/// same scene on another backend in lockstep (the same number of steps, every frame). Every
/// edit, world setting, mouse force and ball-count change goes through here, so it reaches both
/// runs alike.
///
/// The backends step on threads of their own (StepWorker). A step that outlasts the patience
/// (100 ms) is left running and the window goes on drawing the state before it; a later
/// advance() collects it. Anything that changes a backend meanwhile (pausing, editing, world
/// settings, switching) first gives the step up, so the runs continue from the state shown.
class RunController : public QObject {
  Q_OBJECT

 public:
  /// `scene` must be valid; throws std::invalid_argument for an unknown backend.
  RunController(const Scene& scene, const QString& backendName, QObject* parent = nullptr);
  ~RunController() override;

  static constexpr int kMainRun = 0;
  static constexpr int kCompareRun = 1;

  int runCount() const { return compare_ ? 2 : 1; }
  bool comparing() const { return compare_ != nullptr; }
  const Simulation& run(int index) const;
  QString backendName(int index) const { return backendNames_[static_cast<std::size_t>(index)]; }
  QStringList backendNames() const;

  /// 0xRRGGBB per ball, the same in both runs.
  std::span<const std::uint32_t> colours() const { return colours_; }
  BallDef ball(std::size_t index) const;
  std::size_t ballCount() const { return main_->ballCount(); }
  double time() const { return main_->time(); }

  /// The scene Restart and Reset go back to.
  const Scene& loadedScene() const { return loadedScene_; }
  /// Starts every run on `scene` (validated by the caller); attractors and selection go.
  void loadScene(const Scene& scene);
  /// Back to the loaded scene at t = 0, keeping the current world settings and attractors.
  void restart();

  /// Continues run `index` on another backend from the same positions and velocities.
  void setBackend(int index, const QString& name);
  /// Sets a backend option of run `index`; throws std::invalid_argument naming the problem.
  void setBackendOption(int index, const QString& name, double value);
  /// Starts compare mode: both runs restart their clocks from the current state, so they
  /// start identical. Throws std::invalid_argument for an unknown backend.
  void startCompare(const QString& name);
  void stopCompare();

  const WorldSettings& world() const { return main_->world(); }
  void setWorld(const WorldSettings& world);

  const Interactions& interactions() const { return main_->interactions; }
  void setMouseMode(MouseMode mode);
  void setScope(Scope scope);
  void setStrength(double strength);
  std::optional<std::size_t> selected() const { return selected_; }
  void setSelected(std::optional<std::size_t> index);
  void pressTool(Vec2 point);
  void moveTool(Vec2 point);
  void releaseTool(Vec2 point);
  void addAttractor(Vec2 point);
  void clearAttractors();

  /// Adds balls where there is room in every run (the newest are removed first when shrinking).
  /// New balls are sized like the balls there, or smaller when that is what fits (see
  /// newBallScale()). Throws SceneError when they do not fit even so; nothing changes then.
  void setBallCount(std::size_t count);
  /// The size of the balls the last setBallCount() added, relative to the balls already there
  /// (1: the same size).
  double newBallScale() const { return newBallScale_; }
  /// Replaces one ball in every run; throws SceneError (validation) and keeps the state then.
  void setBall(std::size_t index, const BallDef& ball);
  void deleteBall(std::size_t index);

  bool paused() const { return paused_; }
  void setPaused(bool paused);
  /// Real-time driving: runs the whole steps `elapsedSeconds`·`timeScale` holds (none while
  /// paused), the same number in every run. Returns the steps run.
  int advance(double elapsedSeconds, double timeScale);
  /// One step of every run, paused or not.
  void stepOnce();
  StepTiming stepTiming(int index) const { return timing_[static_cast<std::size_t>(index)]; }

  /// How long advance() and stepOnce() wait for a step before leaving it to run in the
  /// background: long enough for any step that keeps a frame rate, short enough to be a hitch
  /// rather than a freeze.
  static constexpr std::chrono::milliseconds kDefaultStepPatience{100};
  /// For runs that must show every step, however slow (headless measurements, tests): an hour.
  static constexpr std::chrono::milliseconds kWaitForEveryStep = std::chrono::hours(1);
  void setStepPatience(std::chrono::milliseconds patience) { stepPatience_ = patience; }
  /// True while a step runs in the background; the runs show the state before it.
  bool stepping() const { return workers_[kMainRun] && workers_[kMainRun]->busy(); }
  /// s the step still running has taken so far (the slower run's), 0 when none.
  double stepSeconds() const;

  /// Zero when not comparing.
  Divergence divergence() const;

 signals:
  /// A backend changed or compare mode started or stopped.
  void runsChanged();
  /// The set of balls changed: a scene was loaded, balls were added, removed or edited.
  void ballsChanged();
  void pausedChanged(bool paused);
  void selectionChanged(std::optional<std::size_t> index);

 private:
  std::unique_ptr<Simulation> makeRun(const Scene& scene, const QString& backendName) const;
  Simulation& runAt(int index) { return index == kCompareRun && compare_ ? *compare_ : *main_; }
  void copyToolsTo(Simulation& run) const;
  /// Backends with a `threads` option (elastic) get the machine's cores, shared between the
  /// runs: this thread waits for the step anyway, and the results are the same for any count.
  /// Set again whenever a backend or the number of runs changes.
  void shareCores();
  /// `count` balls clear of every ball in `room`.
  std::vector<BallDef> placeNewBalls(const Scene& room, std::size_t count, std::uint64_t seed);
  void adoptColours();
  /// Runs `steps` steps of every run; returns how many finished (the last may still be running).
  int stepRuns(int steps);
  /// Finishes the runs' steps if all are done within `patience`; false (nothing finished) if not.
  bool collectSteps(std::chrono::milliseconds patience);
  /// Gives up a step still running (see the class comment), so the backends are here to change.
  void settle();
  void restoreSelection();
  template <class Action>
  void forEachRun(Action&& action);

  Scene loadedScene_;
  std::unique_ptr<Simulation> main_;
  std::unique_ptr<Simulation> compare_;
  std::array<QString, 2> backendNames_;
  std::array<StepTiming, 2> timing_;
  std::array<std::unique_ptr<StepWorker>, 2> workers_;  ///< made at the first step of a run
  std::chrono::milliseconds stepPatience_ = kDefaultStepPatience;
  std::vector<std::uint32_t> colours_;
  std::optional<std::size_t> selected_;
  bool paused_ = false;
  double accumulator_ = 0.0;  ///< s of simulated time not yet stepped
  double newBallScale_ = 1.0;
};

}  // namespace fooball::gui
