#include "run/run_controller.h"

#include <algorithm>
#include <thread>

#include "registry.h"

namespace fooball::gui {

namespace {

std::unique_ptr<Backend> makeBackend(const RunSpec& spec) {
  return createBackend(spec);
}

}  // namespace

RunController::RunController(const Scene& scene, const std::vector<RunSpec>& specs, QObject* parent)
    : QObject(parent), group_(scene, specs, &makeBackend) {
  group_.shareCores(static_cast<int>(std::thread::hardware_concurrency()));
  group_.setHistoryBound(RunHistory::kDefaultBound);
  matchWorkersToRuns();
}

RunController::~RunController() = default;

QString RunController::label(int index) const {
  return QString::fromStdString(group_.spec(std::size_t(index)).text());
}

QStringList RunController::labels() const {
  QStringList labels;
  for (int i = 0; i < runCount(); ++i)
    labels << label(i);
  return labels;
}

void RunController::matchWorkersToRuns() {
  const std::size_t steppers = group_.runCount() + (group_.hasBaseline() ? 1 : 0);
  workers_.resize(steppers);
  for (auto& worker : workers_) {
    if (!worker) worker = std::make_unique<StepWorker>();
  }
  timing_.resize(group_.runCount());
}

void RunController::loadScene(const Scene& scene) {
  settle();
  group_.load(scene);
  emit selectionChanged(std::nullopt);
  emit ballsChanged();
}

void RunController::restart() {
  settle();
  group_.restart();
  emit selectionChanged(std::nullopt);
  emit ballsChanged();
}

Scene RunController::savedScene() {
  settle();
  return group_.savedScene();
}

void RunController::setRunSpec(int index, const RunSpec& spec) {
  settle();
  group_.setSpec(std::size_t(index), spec);
  emit runsChanged();
}

void RunController::setBackendOption(int index, const QString& name, double value) {
  settle();
  group_.setOption(std::size_t(index), name.toStdString(), value);
  emit optionsChanged(index);
}

void RunController::addRun(const RunSpec& spec) {
  settle();
  group_.addRun(spec);
  matchWorkersToRuns();
  timing_.back() = {};
  emit runsChanged();
  emit runsRestarted(group_.time());
}

void RunController::removeRun(int index) {
  settle();
  const std::size_t before = group_.runCount();
  group_.removeRun(std::size_t(index));
  if (group_.runCount() == before) return;
  timing_.erase(timing_.begin() + index);
  matchWorkersToRuns();
  emit runsChanged();
}

void RunController::setBaseline(bool on) {
  if (on == group_.hasBaseline()) return;
  settle();
  group_.setBaseline(on);
  matchWorkersToRuns();
  emit runsChanged();
}

void RunController::setSelected(std::optional<std::size_t> index) {
  if (index && *index >= group_.ballCount()) index.reset();
  if (index == group_.selected()) return;
  group_.setSelected(index);
  emit selectionChanged(index);
}

void RunController::setBallCount(std::size_t count) {
  settle();
  const auto selectedBefore = group_.selected();
  group_.setBallCount(count);
  if (group_.selected() != selectedBefore) emit selectionChanged(group_.selected());
  emit ballsChanged();
}

void RunController::setBall(std::size_t index, const BallDef& ball) {
  settle();
  group_.setBall(index, ball);
  emit ballsChanged();
}

BallDef RunController::editBall(std::size_t index, const BallDef& edited) {
  settle();
  const BallDef set = group_.editBall(index, edited);
  emit ballsChanged();
  return set;
}

void RunController::restoreBall(std::size_t index, const BallStates& saved,
                                BallPlacement placement) {
  settle();
  group_.restoreBall(index, saved, placement);
  emit ballsChanged();
}

void RunController::deleteBall(std::size_t index) {
  settle();
  group_.deleteBall(index);
  emit selectionChanged(std::nullopt);
  emit ballsChanged();
}

void RunController::setPaused(bool paused) {
  if (paused) settle();  // pausing stops what is shown, including a slow step
  if (paused == group_.paused()) return;
  group_.setPaused(paused);
  emit pausedChanged(paused);
}

int RunController::advance(double elapsedSeconds, double timeScale,
                           const std::function<void()>& whileFirstStepRuns) {
  if (stepping()) return collectSteps(std::chrono::milliseconds(0)) ? 1 : 0;
  return stepRuns(group_.takeDueSteps(elapsedSeconds, timeScale, lastStepSeconds_), stepPatience_,
                  whileFirstStepRuns);
}

int RunController::advanceExactly(double simulatedSeconds,
                                  const std::function<void()>& whileFirstStepRuns) {
  // A step out in the background was due before this frame: it belongs to the time before.
  const int collected = stepping() && collectSteps(kWaitForEveryStep) ? 1 : 0;
  return collected +
         stepRuns(group_.takeStepsFor(simulatedSeconds), kWaitForEveryStep, whileFirstStepRuns);
}

void RunController::rewindTo(std::size_t index) {
  settle();
  group_.rewindTo(index);
  emit rewound(group_.time());
}

void RunController::stepBack() {
  settle();
  group_.stepBack();
  emit rewound(group_.time());
}

void RunController::stepOnce() {
  if (!stepping()) stepRuns(1, stepPatience_);
}

int RunController::stepRuns(int steps, std::chrono::milliseconds patience,
                            const std::function<void()>& whileFirstStepRuns) {
  for (int finished = 0; finished < steps; ++finished) {
    group_.beginSteps(steps_);
    for (std::size_t i = 0; i < steps_.size(); ++i)
      workers_[i]->start(std::move(steps_[i]));
    if (finished == 0 && whileFirstStepRuns) {
      stepsOut_ = steps;
      whileFirstStepRuns();
      stepsOut_ = 0;
    }
    if (!collectSteps(patience)) {
      group_.dropBacklog();  // a slow step: no catching up after it
      return finished;
    }
    // Every run failed (RunGroup::finishSteps): they are paused where that step began.
    if (group_.paused()) return finished;
  }
  return steps;
}

bool RunController::collectSteps(std::chrono::milliseconds patience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    if (!workers_[i]->finishedBy(deadline)) return false;
  }
  lastStepSeconds_ = 0.0;
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const double seconds = workers_[i]->seconds();
    lastStepSeconds_ = std::max(lastStepSeconds_, seconds);
    if (i < timing_.size()) {
      timing_[i].millisecondsPerStep = seconds * 1e3;
      ++timing_[i].stepsTaken;
    }
    steps_[i] = workers_[i]->take();
  }
  const std::vector<RunGroup::StepFailure> failures = group_.finishSteps(steps_);
  if (!failures.empty()) reportFailures(failures);
  return true;
}

void RunController::reportFailures(const std::vector<RunGroup::StepFailure>& failures) {
  const bool removing = group_.runCount() < timing_.size();
  QStringList lines;
  QList<int> removed;
  for (auto failure = failures.rbegin(); failure != failures.rend(); ++failure) {
    if (removing && failure->run) {
      timing_.erase(timing_.begin() + std::ptrdiff_t(*failure->run));
      removed.append(int(*failure->run));
    }
    lines.prepend(
        tr("%1 stopped: %2")
            .arg(QString::fromStdString(failure->label), QString::fromStdString(failure->message)));
  }
  matchWorkersToRuns();
  emit runsChanged();
  if (group_.paused()) emit pausedChanged(true);
  emit runsFailed(lines.join(QLatin1Char('\n')), removed);
}

void RunController::settle() {
  if (!stepping() || collectSteps(std::chrono::milliseconds(0))) return;
  // Destroying a worker mid-step gives its step up; the next step gets a new worker.
  for (std::size_t i = 0; i < steps_.size(); ++i)
    workers_[i] = std::make_unique<StepWorker>();
  steps_.clear();
  group_.abandonSteps();
}

double RunController::stepSeconds() const {
  if (!stepping()) return 0.0;
  double seconds = 0.0;
  for (const auto& worker : workers_) {
    if (worker->busy()) seconds = std::max(seconds, worker->seconds());
  }
  return seconds;
}

}  // namespace fooball::gui
