#include "run_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <utility>

#include "fooball/metrics.h"
#include "fooball/random_balls.h"
#include "fooball/scene_error.h"
#include "registry.h"

namespace fooball::gui {

namespace {

/// At most this many steps per frame per unit of time scale: enough to catch up after a
/// hiccup, few enough that a slow machine slows the simulation down instead of freezing.
constexpr double kMaxStepsPerFramePerTimeScale = 4.0;

/// New balls get the size range of the balls already there, or this one in an empty box.
constexpr double kDefaultMinRadius = 0.1;  // m
constexpr double kDefaultMaxRadius = 0.3;  // m
/// When they do not fit at that size they shrink, at most to this fraction of it…
constexpr double kMinNewBallScale = 0.01;
/// …aiming at lattice cells this much wider than a ball, shrinking further if need be.
constexpr double kLatticeFill = 0.8;
constexpr double kShrinkPerAttempt = 0.8;
constexpr int kMaxPlacementAttempts = 8;

}  // namespace

RunController::RunController(const Scene& scene, const QString& backendName, QObject* parent)
    : QObject(parent), loadedScene_(scene) {
  main_ = makeRun(scene, backendName);
  backendNames_[kMainRun] = backendName;
  adoptColours();
  shareCores();
}

RunController::~RunController() = default;

std::unique_ptr<Simulation> RunController::makeRun(const Scene& scene,
                                                   const QString& backendName) const {
  return std::make_unique<Simulation>(scene, createBackend(backendName.toStdString()));
}

const Simulation& RunController::run(int index) const {
  return index == kCompareRun && compare_ ? *compare_ : *main_;
}

QStringList RunController::backendNames() const {
  QStringList names{backendNames_[kMainRun]};
  if (compare_) names.append(backendNames_[kCompareRun]);
  return names;
}

template <class Action>
void RunController::forEachRun(Action&& action) {
  action(*main_);
  if (compare_) action(*compare_);
}

BallDef RunController::ball(std::size_t index) const {
  return {main_->positions()[index], main_->velocities()[index], main_->radii()[index],
          main_->masses()[index], colours_[index]};
}

void RunController::adoptColours() {
  const Scene scene = main_->scene();
  colours_.resize(scene.balls.size());
  std::transform(scene.balls.begin(), scene.balls.end(), colours_.begin(),
                 [](const BallDef& b) { return b.color; });
}

void RunController::loadScene(const Scene& scene) {
  settle();
  loadedScene_ = scene;
  selected_.reset();
  forEachRun([&](Simulation& run) {
    run.interactions.clearAttractors();
    run.load(scene);
  });
  adoptColours();
  emit selectionChanged(selected_);
  emit ballsChanged();
}

void RunController::restart() {
  settle();
  Scene scene = loadedScene_;
  scene.world = world();
  forEachRun([&](Simulation& run) { run.load(scene); });
  selected_.reset();
  adoptColours();
  emit selectionChanged(selected_);
  emit ballsChanged();
}

void RunController::setBackend(int index, const QString& name) {
  settle();
  const int target = index == kCompareRun && compare_ ? kCompareRun : kMainRun;
  runAt(target).setBackend(createBackend(name.toStdString()));
  backendNames_[static_cast<std::size_t>(target)] = name;
  shareCores();
  emit runsChanged();
}

void RunController::setBackendOption(int index, const QString& name, double value) {
  settle();
  runAt(index).backend().setOption(name.toStdString(), value);
}

void RunController::shareCores() {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int perRun = std::max(1, cores / runCount());
  forEachRun([&](Simulation& run) {
    Backend& backend = run.backend();
    const auto specs = backend.options().specs();
    const auto threads = std::find_if(
        specs.begin(), specs.end(), [](const OptionSpec& spec) { return spec.name == "threads"; });
    if (threads != specs.end())
      backend.setOption(threads->name, std::clamp(double(perRun), threads->min, threads->max));
  });
}

void RunController::copyToolsTo(Simulation& run) const {
  run.interactions.mode = main_->interactions.mode;
  run.interactions.scope = main_->interactions.scope;
  run.interactions.strength = main_->interactions.strength;
  run.interactions.selected = selected_;
  run.interactions.clearAttractors();
  for (const Vec2 attractor : main_->interactions.attractors())
    run.interactions.addAttractor(attractor);
}

void RunController::startCompare(const QString& name) {
  settle();
  // Both runs restart their clocks on the current state, so the charts start together.
  const Scene now = main_->scene();
  auto second = makeRun(now, name);
  main_->load(now);
  compare_ = std::move(second);
  copyToolsTo(*compare_);
  restoreSelection();
  backendNames_[kCompareRun] = name;
  timing_[kCompareRun] = {};
  shareCores();
  emit runsChanged();
}

void RunController::stopCompare() {
  settle();
  if (!compare_) return;
  compare_.reset();
  workers_[kCompareRun].reset();
  backendNames_[kCompareRun].clear();
  shareCores();
  emit runsChanged();
}

void RunController::setWorld(const WorldSettings& world) {
  settle();
  forEachRun([&](Simulation& run) { run.setWorld(world); });
}

void RunController::setMouseMode(MouseMode mode) {
  forEachRun([&](Simulation& run) { run.interactions.mode = mode; });
}

void RunController::setScope(Scope scope) {
  forEachRun([&](Simulation& run) { run.interactions.scope = scope; });
}

void RunController::setStrength(double strength) {
  forEachRun([&](Simulation& run) { run.interactions.strength = strength; });
}

void RunController::setSelected(std::optional<std::size_t> index) {
  if (index && *index >= ballCount()) index.reset();
  if (index == selected_) return;
  selected_ = index;
  restoreSelection();
  emit selectionChanged(selected_);
}

void RunController::restoreSelection() {
  forEachRun([&](Simulation& run) { run.interactions.selected = selected_; });
}

void RunController::pressTool(Vec2 point) {
  forEachRun([&](Simulation& run) { run.interactions.press(point, run.balls()); });
}

void RunController::moveTool(Vec2 point) {
  forEachRun([&](Simulation& run) { run.interactions.move(point); });
}

void RunController::releaseTool(Vec2 point) {
  forEachRun([&](Simulation& run) { run.interactions.release(point); });
}

void RunController::addAttractor(Vec2 point) {
  forEachRun([&](Simulation& run) { run.interactions.addAttractor(point); });
}

void RunController::clearAttractors() {
  forEachRun([&](Simulation& run) { run.interactions.clearAttractors(); });
}

std::vector<BallDef> RunController::placeNewBalls(const Scene& room, std::size_t count,
                                                  std::uint64_t seed) {
  RandomBalls spec;
  spec.count = count;
  spec.seed = seed;
  spec.minRadius = kDefaultMinRadius;
  spec.maxRadius = kDefaultMaxRadius;
  const auto radii = main_->radii();
  if (!radii.empty()) {
    const auto [smallest, largest] = std::minmax_element(radii.begin(), radii.end());
    spec.minRadius = *smallest;
    spec.maxRadius = *largest;
  }
  // Sized like the balls there if they fit; otherwise smaller, as the free area allows: balls
  // go one per lattice cell of side 2·maxRadius, so maxRadius ≈ √(free area / count) / 2.
  // (The compare run's balls cover the same area, so they count once.)
  double freeArea = room.box.width * room.box.height;
  for (const double radius : radii)
    freeArea -= std::numbers::pi * radius * radius;
  const double fittingRadius =
      kLatticeFill * 0.5 * std::sqrt(std::max(freeArea, 0.0) / double(count));
  const double scale = std::min(1.0, fittingRadius / spec.maxRadius);
  const auto tooSmall = [&](double factor) {
    return SceneError("cannot add " + std::to_string(count) + " balls: they do not fit even at " +
                      std::to_string(std::lround(100.0 * factor)) +
                      " % of the size of the balls there");
  };
  if (scale < kMinNewBallScale) throw tooSmall(kMinNewBallScale);
  newBallScale_ = scale;
  for (int attempt = 0;; ++attempt) {
    RandomBalls scaled = spec;
    scaled.minRadius *= newBallScale_;
    scaled.maxRadius *= newBallScale_;
    Scene trial = room;
    try {
      addRandomBalls(trial, scaled);
      return {trial.balls.begin() + static_cast<std::ptrdiff_t>(room.balls.size()),
              trial.balls.end()};
    } catch (const SceneError&) {
      if (attempt == kMaxPlacementAttempts ||
          newBallScale_ * kShrinkPerAttempt < kMinNewBallScale) {
        throw tooSmall(newBallScale_);
      }
      newBallScale_ *= kShrinkPerAttempt;
    }
  }
}

void RunController::setBallCount(std::size_t count) {
  settle();
  const std::size_t current = ballCount();
  newBallScale_ = 1.0;
  if (count == current) return;
  std::vector<BallDef> mainBalls = main_->scene().balls;
  std::vector<BallDef> compareBalls = compare_ ? compare_->scene().balls : std::vector<BallDef>{};
  if (count < current) {
    mainBalls.resize(count);
    compareBalls.resize(std::min(count, compareBalls.size()));
  } else {
    // New balls must clear the balls of both runs, which differ once the runs diverge.
    Scene room = main_->scene();
    room.balls.insert(room.balls.end(), compareBalls.begin(), compareBalls.end());
    const std::vector<BallDef> added = placeNewBalls(room, count - current, main_->steps() + count);
    std::size_t index = current;
    for (BallDef ball : added) {
      ball.color = defaultBallColor(index++);
      mainBalls.push_back(ball);
      compareBalls.push_back(ball);
    }
  }
  main_->replaceBalls(std::move(mainBalls));
  if (compare_) compare_->replaceBalls(std::move(compareBalls));
  if (selected_ && *selected_ >= count) selected_.reset();
  restoreSelection();
  adoptColours();
  emit selectionChanged(selected_);
  emit ballsChanged();
}

void RunController::setBall(std::size_t index, const BallDef& ball) {
  settle();
  const BallDef before = this->ball(index);
  main_->setBall(index, ball);
  if (compare_) {
    try {
      compare_->setBall(index, ball);
    } catch (const SceneError&) {
      main_->setBall(index, before);  // both runs keep the same balls, or neither changes
      throw;
    }
  }
  colours_[index] = ball.color;
  emit ballsChanged();
}

void RunController::deleteBall(std::size_t index) {
  settle();
  if (index >= ballCount()) return;
  forEachRun([&](Simulation& run) {
    std::vector<BallDef> balls = run.scene().balls;
    balls.erase(balls.begin() + static_cast<std::ptrdiff_t>(index));
    run.replaceBalls(std::move(balls));
  });
  selected_.reset();
  restoreSelection();
  adoptColours();
  emit selectionChanged(selected_);
  emit ballsChanged();
}

void RunController::setPaused(bool paused) {
  if (paused) settle();  // pausing stops what is shown, including a slow step
  if (paused == paused_) return;
  paused_ = paused;
  accumulator_ = 0.0;
  emit pausedChanged(paused_);
}

int RunController::advance(double elapsedSeconds, double timeScale) {
  if (stepping()) return collectSteps(std::chrono::milliseconds(0)) ? 1 : 0;
  if (paused_) return 0;
  const double dt = main_->dt();
  accumulator_ += elapsedSeconds * timeScale;
  const int maxSteps =
      std::max(1, static_cast<int>(std::ceil(kMaxStepsPerFramePerTimeScale * timeScale)));
  const int steps = static_cast<int>(std::min(std::floor(accumulator_ / dt), double(maxSteps)));
  accumulator_ = steps == maxSteps ? 0.0 : accumulator_ - steps * dt;
  return stepRuns(steps);
}

void RunController::stepOnce() {
  if (!stepping()) stepRuns(1);
}

int RunController::stepRuns(int steps) {
  for (int finished = 0; finished < steps; ++finished) {
    for (int i = 0; i < runCount(); ++i) {
      std::unique_ptr<StepWorker>& worker = workers_[static_cast<std::size_t>(i)];
      if (!worker) worker = std::make_unique<StepWorker>();
      worker->start(runAt(i).beginStep());
    }
    if (!collectSteps(stepPatience_)) {
      accumulator_ = 0.0;  // a slow step: no catching up after it
      return finished;
    }
  }
  return steps;
}

bool RunController::collectSteps(std::chrono::milliseconds patience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  for (int i = 0; i < runCount(); ++i) {
    if (!workers_[static_cast<std::size_t>(i)]->finishedBy(deadline)) return false;
  }
  for (int i = 0; i < runCount(); ++i) {
    const auto index = static_cast<std::size_t>(i);
    timing_[index].millisecondsPerStep = workers_[index]->seconds() * 1e3;
    ++timing_[index].stepsTaken;
    runAt(i).finishStep(workers_[index]->take());
  }
  return true;
}

void RunController::settle() {
  if (!stepping() || collectSteps(std::chrono::milliseconds(0))) return;
  for (int i = 0; i < runCount(); ++i) {
    const auto index = static_cast<std::size_t>(i);
    std::unique_ptr<Backend> fresh = createBackend(backendNames_[index].toStdString());
    const OptionSet& options = workers_[index]->backend().options();
    for (const OptionSpec& spec : options.specs())
      fresh->setOption(spec.name, options.value(spec.name));
    workers_[index].reset();  // gives the step up; the next step gets a new worker
    runAt(i).abandonStep(std::move(fresh));
  }
}

double RunController::stepSeconds() const {
  double seconds = 0.0;
  for (const auto& worker : workers_) {
    if (worker && worker->busy()) seconds = std::max(seconds, worker->seconds());
  }
  return seconds;
}

Divergence RunController::divergence() const {
  Divergence result;
  if (!compare_) return result;
  const auto a = main_->positions();
  const auto b = compare_->positions();
  const std::size_t count = std::min(a.size(), b.size());
  double sumSquares = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double squared = lengthSquared(b[i] - a[i]);
    sumSquares += squared;
    result.maxPositionDifference = std::max(result.maxPositionDifference, squared);
  }
  result.maxPositionDifference = std::sqrt(result.maxPositionDifference);
  result.rmsPositionDifference = count > 0 ? std::sqrt(sumSquares / double(count)) : 0.0;
  const StateSums mainSums =
      sumState(a, main_->velocities(), main_->masses(), main_->world().gravity);
  const StateSums compareSums =
      sumState(b, compare_->velocities(), compare_->masses(), compare_->world().gravity);
  result.energyDifference = compareSums.totalEnergy() - mainSums.totalEnergy();
  const double reference = std::abs(mainSums.totalEnergy());
  result.relativeEnergyDifference = reference > 0.0 ? result.energyDifference / reference : 0.0;
  result.momentumDifference = length(compareSums.momentum - mainSums.momentum);
  return result;
}

}  // namespace fooball::gui
