#include "fooball/run_group.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fooball/ball_placement.h"
#include "fooball/scene_error.h"
#include "fooball/split_mix64.h"

namespace fooball {

RunGroup::RunGroup(const Scene& scene, const std::vector<RunSpec>& specs, BackendFactory factory)
    : factory_(factory), loadedScene_(scene) {
  if (specs.empty() || specs.size() > kMaxRuns) {
    throw std::invalid_argument("a run group holds 1 to " + std::to_string(kMaxRuns) +
                                " runs (got " + std::to_string(specs.size()) + ")");
  }
  for (const RunSpec& spec : specs)
    runs_.push_back({spec, makeSimulation(scene, spec)});
  history_.setBound(0);
}

RunGroup::~RunGroup() = default;

std::unique_ptr<Backend> RunGroup::makeBackend(const RunSpec& spec) const {
  std::unique_ptr<Backend> backend = factory_(spec);
  applyCores(*backend);
  return backend;
}

std::unique_ptr<Simulation> RunGroup::makeSimulation(const Scene& scene,
                                                     const RunSpec& spec) const {
  auto simulation = std::make_unique<Simulation>(scene, makeBackend(spec));
  if (!runs_.empty()) {
    simulation->setDt(dt());
    copyToolsTo(*simulation);
  }
  return simulation;
}

void RunGroup::copyToolsTo(Simulation& simulation) const {
  const Interactions& tools = interactions();
  simulation.interactions.mode = tools.mode;
  simulation.interactions.scope = tools.scope;
  simulation.interactions.strength = tools.strength;
  simulation.interactions.selected = tools.selected;
  simulation.interactions.clearAttractors();
  for (const Vec2 attractor : tools.attractors())
    simulation.interactions.addAttractor(attractor);
}

template <class Action>
void RunGroup::forEachSimulation(Action&& action) {
  for (Run& run : runs_)
    action(*run.simulation);
  if (baseline_) action(*baseline_);
}

std::vector<std::string> RunGroup::labels() const {
  std::vector<std::string> labels;
  for (const Run& run : runs_)
    labels.push_back(run.spec.text());
  return labels;
}

void RunGroup::addRun(const RunSpec& spec) {
  if (runs_.size() == kMaxRuns) {
    throw std::invalid_argument("run spec '" + spec.text() + "': a run group holds at most " +
                                std::to_string(kMaxRuns) + " runs");
  }
  runs_.push_back({spec, makeSimulation(scene(), spec)});
  shareCores(cores_);
  synchronise();
}

void RunGroup::removeRun(std::size_t index) {
  if (runs_.size() < 2 || index >= runs_.size()) return;
  runs_.erase(runs_.begin() + static_cast<std::ptrdiff_t>(index));
  if (index == 0 && baseline_) setBaseline(true);  // the baseline follows the new reference
  shareCores(cores_);
  restartHistory();
}

void RunGroup::setSpec(std::size_t index, const RunSpec& spec) {
  Run& run = runs_.at(index);
  run.simulation->setBackend(makeBackend(spec));
  run.spec = spec;
  if (index == 0 && baseline_) setBaseline(true);  // a copy of run 0 has run 0's method
  restartHistory();
}

void RunGroup::setOption(std::size_t index, std::string_view name, double value) {
  Run& run = runs_.at(index);
  run.simulation->backend().setOption(name, value);
  run.spec.set(name, value);
  if (index == 0 && baseline_) baseline_->backend().setOption(name, value);
  restartHistory(true);
}

void RunGroup::synchronise() {
  const Scene now = scene();
  const double clock = time();
  for (Run& run : runs_)
    run.simulation->load(now, clock);
  if (baseline_) setBaseline(true);
  restartHistory();
}

void RunGroup::shareCores(int cores) {
  cores_ = std::max(1, cores);
  forEachSimulation([&](Simulation& simulation) { applyCores(simulation.backend()); });
}

void RunGroup::applyCores(Backend& backend) const {
  const OptionSpec* threads = backend.options().withRole(OptionRole::Threads);
  if (!threads) return;
  const double perRun = std::max(1.0, std::floor(double(cores_) / double(stepperCount())));
  backend.setOption(threads->name, std::clamp(perRun, threads->min, threads->max));
}

Divergence RunGroup::divergence(std::size_t index) const {
  return measureDivergence(run(0), run(index));
}

Scene RunGroup::displacedScene() const {
  Scene displaced = scene();
  SplitMix64 random(kBaselineSeed);
  for (BallDef& ball : displaced.balls) {
    const double angle = random.between(0.0, 2.0 * std::numbers::pi);
    ball.position += kBaselineDisplacement * Vec2{std::cos(angle), std::sin(angle)};
  }
  return displaced;
}

void RunGroup::setBaseline(bool on) {
  if (!on) {
    baseline_.reset();
  } else {
    const Scene displaced = displacedScene();
    baseline_ = makeSimulation(displaced, runs_.front().spec);
    baseline_->load(displaced, time());  // on run 0's clock
  }
  shareCores(cores_);
  restartHistory();
}

std::optional<Divergence> RunGroup::baselineDivergence() const {
  if (!baseline_) return std::nullopt;
  return measureDivergence(run(0), *baseline_);
}

GroupDivergences RunGroup::divergences() const {
  GroupDivergences now;
  now.time = time();
  for (std::size_t i = 0; i < runCount(); ++i)
    now.fromRunZero.push_back(divergence(i));
  now.baseline = baselineDivergence();
  return now;
}

void RunGroup::load(const Scene& scene) {
  loadedScene_ = scene;
  forEachSimulation([&](Simulation& simulation) {
    simulation.interactions.clearAttractors();
    simulation.interactions.selected.reset();
    simulation.load(scene);
  });
  massChosen_.clear();
  if (baseline_) setBaseline(true);
  restartHistory();
}

void RunGroup::restart() {
  const std::size_t count = ballCount();
  Scene scene = loadedScene_;
  scene.world = world();
  scene.dt = dt();  // a setting, like the world
  forEachSimulation([&](Simulation& simulation) {
    simulation.interactions.selected.reset();
    simulation.load(scene);
  });
  massChosen_.clear();  // the balls as loaded
  // The ball count is a setting like gravity: the loaded balls, then the newest removed or new
  // ones placed as the spinner places them (the same at every restart: placed at step 0).
  setBallCount(count);
  if (baseline_) setBaseline(true);
  restartHistory();
}

void RunGroup::setWorld(const WorldSettings& world) {
  forEachSimulation([&](Simulation& simulation) { simulation.setWorld(world); });
  restartHistory();
}

BallDef RunGroup::ball(std::size_t index) const {
  const Simulation& reference = run(0);
  return {reference.positions()[index], reference.velocities()[index], reference.radii()[index],
          reference.masses()[index], reference.colours()[index]};
}

Scene RunGroup::newBallRoom() const {
  Scene room = scene();
  room.balls.clear();
  const auto add = [&](const Simulation& simulation) {
    const Scene state = simulation.scene();
    room.balls.insert(room.balls.end(), state.balls.begin(), state.balls.end());
  };
  for (const Run& run : runs_)
    add(*run.simulation);
  if (baseline_) add(*baseline_);
  return room;
}

std::size_t RunGroup::mostBallsThatFit() const {
  return ballCount() + mostNewBallsThatFit(newBallRoom(), stepperCount());
}

void RunGroup::setBallCount(std::size_t count) {
  const std::size_t current = ballCount();
  newBallScale_ = 1.0;
  if (count == current) return;
  PlacedBalls added;
  if (count > current) {
    added = placeNewBalls(newBallRoom(), stepperCount(), count - current, current, steps() + count);
    newBallScale_ = added.scale;
  }
  forEachSimulation([&](Simulation& simulation) {
    std::vector<BallDef> balls = simulation.scene().balls;
    balls.resize(std::min(count, balls.size()));
    balls.insert(balls.end(), added.balls.begin(), added.balls.end());
    simulation.replaceBalls(std::move(balls));
  });
  massChosen_.resize(std::min(count, massChosen_.size()));
  if (selected() && *selected() >= count) setSelected(std::nullopt);
  restartHistory();
}

void RunGroup::setBall(std::size_t index, const BallDef& ball) {
  // Every run gets the edit, or none does: a run that refuses it (the ball would overlap one of
  // its own) undoes it in the runs before, each back to the ball it had, which was valid there.
  std::vector<std::pair<Simulation*, BallDef>> changed;
  try {
    forEachSimulation([&](Simulation& simulation) {
      const BallDef before{simulation.positions()[index], simulation.velocities()[index],
                           simulation.radii()[index], simulation.masses()[index],
                           simulation.colours()[index]};
      simulation.setBall(index, ball);
      changed.emplace_back(&simulation, before);
    });
  } catch (const SceneError&) {
    for (const auto& [simulation, before] : changed)
      simulation->setBall(index, before);
    throw;
  }
  restartHistory();
}

BallDef RunGroup::editBall(std::size_t index, BallDef edited) {
  const BallDef current = ball(index);
  const bool massEdited = edited.mass != current.mass;
  if (!massEdited && !massChosen(index) && edited.radius != current.radius) {
    const double scale = edited.radius / current.radius;
    edited.mass = current.mass * scale * scale;
  }
  setBall(index, edited);
  if (massEdited) {
    massChosen_.resize(ballCount());
    massChosen_[index] = true;
  }
  return edited;
}

void RunGroup::deleteBall(std::size_t index) {
  if (index >= ballCount()) return;
  forEachSimulation([&](Simulation& simulation) {
    std::vector<BallDef> balls = simulation.scene().balls;
    balls.erase(balls.begin() + static_cast<std::ptrdiff_t>(index));
    simulation.replaceBalls(std::move(balls));
  });
  if (index < massChosen_.size()) massChosen_.erase(massChosen_.begin() + std::ptrdiff_t(index));
  setSelected(std::nullopt);
  restartHistory();
}

BallStates RunGroup::ballStates(std::size_t index) const {
  BallStates saved{{}, massChosen(index)};
  const auto stateOf = [index](const Simulation& simulation) {
    return BallDef{simulation.positions()[index], simulation.velocities()[index],
                   simulation.radii()[index], simulation.masses()[index],
                   simulation.colours()[index]};
  };
  for (const Run& run : runs_)
    saved.states.push_back(stateOf(*run.simulation));
  if (baseline_) saved.states.push_back(stateOf(*baseline_));
  return saved;
}

const BallDef& RunGroup::savedState(const BallStates& saved, std::size_t k) const {
  return saved.states.size() == stepperCount() ? saved.states[k] : saved.states.front();
}

std::optional<BallProblem> RunGroup::findRestoreProblem(std::size_t index, const BallStates& saved,
                                                        BallPlacement placement) const {
  const std::optional<std::size_t> replacing =
      placement == BallPlacement::Replace ? std::optional(index) : std::nullopt;
  std::size_t k = 0;
  std::optional<BallProblem> problem;
  const auto check = [&](const Simulation& simulation) {
    const BallDef& state = savedState(saved, k++);
    if (!problem) problem = findBallProblem(state, simulation.box(), world().walls);
    if (!problem && world().ballCollisions) {
      problem = findOverlapProblem(state, simulation.positions(), simulation.radii(), replacing);
    }
  };
  for (const Run& run : runs_)
    check(*run.simulation);
  if (baseline_) check(*baseline_);
  return problem;
}

void RunGroup::restoreBall(std::size_t index, const BallStates& saved, BallPlacement placement) {
  const std::size_t limit = ballCount() + (placement == BallPlacement::Insert ? 1 : 0);
  if (index >= limit || saved.states.empty()) {
    throw SceneError("balls[" + std::to_string(index) + "]: no such place to put a ball back");
  }
  if (const auto problem = findRestoreProblem(index, saved, placement)) {
    throw BallError(
        "balls[" + std::to_string(index) + "]: cannot be put back: " + plainWords(*problem),
        *problem);
  }
  std::size_t k = 0;
  forEachSimulation([&](Simulation& simulation) {
    const BallDef& state = savedState(saved, k++);
    if (placement == BallPlacement::Insert) {
      simulation.insertBall(index, state);
    } else {
      simulation.setBall(index, state);
    }
  });
  massChosen_.resize(ballCount() - (placement == BallPlacement::Insert ? 1 : 0));
  if (placement == BallPlacement::Insert) {
    massChosen_.insert(massChosen_.begin() + std::ptrdiff_t(index), saved.massChosen);
  } else {
    massChosen_[index] = saved.massChosen;
  }
  restartHistory();
}

void RunGroup::setMouseMode(MouseMode mode) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.mode = mode; });
}

void RunGroup::setScope(Scope scope) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.scope = scope; });
}

void RunGroup::setStrength(double strength) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.strength = strength; });
}

void RunGroup::setSelected(std::optional<std::size_t> index) {
  if (index && *index >= ballCount()) index.reset();
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.selected = index; });
}

void RunGroup::pressTool(Vec2 point) {
  forEachSimulation(
      [&](Simulation& simulation) { simulation.interactions.press(point, simulation.balls()); });
}

void RunGroup::moveTool(Vec2 point) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.move(point); });
}

void RunGroup::releaseTool(Vec2 point) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.release(point); });
}

void RunGroup::addAttractor(Vec2 point) {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.addAttractor(point); });
}

void RunGroup::clearAttractors() {
  forEachSimulation([&](Simulation& simulation) { simulation.interactions.clearAttractors(); });
}

void RunGroup::setDt(double dt) {
  forEachSimulation([&](Simulation& simulation) { simulation.setDt(dt); });
  restartHistory();
}

void RunGroup::step() {
  forEachSimulation([&](Simulation& simulation) { simulation.step(); });
  recordHistory();
}

void RunGroup::runFor(double seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) return;
  const auto count = static_cast<std::uint64_t>(std::llround(seconds / dt()));
  for (std::uint64_t i = 0; i < count; ++i)
    step();
}

void RunGroup::beginSteps(std::vector<BackendStep>& steps) {
  steps.clear();
  forEachSimulation([&](Simulation& simulation) { steps.push_back(simulation.beginStep()); });
  stepping_ = true;
}

std::vector<RunGroup::StepFailure> RunGroup::finishSteps(std::vector<BackendStep>& steps) {
  stepping_ = false;
  std::vector<StepFailure> failures;
  std::vector<std::size_t> failedRuns;
  bool baselineFailed = false;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i].failure().empty()) continue;
    if (i == runs_.size()) {
      baselineFailed = true;
      failures.push_back({std::nullopt, "baseline", steps[i].failure()});
    } else {
      failedRuns.push_back(i);
      failures.push_back({i, runs_[i].spec.text(), steps[i].failure()});
    }
  }
  if (!failedRuns.empty() && failedRuns.size() == runs_.size()) {
    // Nothing to go on with: back to the state before the step, in lockstep, paused.
    steps.clear();
    for (Run& run : runs_)
      run.simulation->abandonStep(makeBackend(run.spec));
    if (baseline_) baseline_->abandonStep(makeBackend(runs_.front().spec));
    setPaused(true);
    restartHistory();
    return failures;
  }
  std::size_t next = 0;
  forEachSimulation([&](Simulation& simulation) {
    BackendStep& step = steps[next++];
    if (step.failure().empty()) simulation.finishStep(std::move(step));
  });
  steps.clear();
  if (failures.empty()) {
    recordHistory();
    return failures;
  }
  for (auto index = failedRuns.rbegin(); index != failedRuns.rend(); ++index)
    runs_.erase(runs_.begin() + static_cast<std::ptrdiff_t>(*index));
  // A baseline is run 0's copy: it starts again from the new run 0, or where its own step failed.
  if (baseline_ && (baselineFailed || (!failedRuns.empty() && failedRuns.front() == 0)))
    setBaseline(true);
  shareCores(cores_);
  restartHistory();
  return failures;
}

void RunGroup::abandonSteps() {
  if (!stepping_) return;
  for (Run& run : runs_)
    run.simulation->abandonStep(makeBackend(run.spec));
  if (baseline_) baseline_->abandonStep(makeBackend(runs_.front().spec));
  stepping_ = false;
  restartHistory();
}

void RunGroup::setPaused(bool paused) {
  paused_ = paused;
  accumulator_ = 0.0;
}

int RunGroup::takeDueSteps(double elapsedSeconds, double timeScale, double secondsPerStep) {
  if (paused_) return 0;
  const double simulated = elapsedSeconds * timeScale;
  if (simulated > 0.0 && std::isfinite(simulated)) accumulator_ += simulated;
  int maxSteps =
      std::max(1, static_cast<int>(std::ceil(kMaxStepsPerFramePerTimeScale * timeScale)));
  if (secondsPerStep > 0.0) {
    const double affordable = std::floor(kSteppingPerFrame / secondsPerStep);
    if (affordable < maxSteps) maxSteps = std::max(1, static_cast<int>(affordable));
  }
  const double due = std::floor(accumulator_ / dt());
  // Only a backlog beyond the cap is dropped: a frame that is due exactly the cap keeps the
  // fraction of a step not due yet, or a machine that keeps up would lose real time.
  if (due > maxSteps) {
    accumulator_ = 0.0;  // the machine cannot keep up: drop the backlog rather than spiral
    return maxSteps;
  }
  const int count = static_cast<int>(due);
  accumulator_ -= count * dt();
  return count;
}

int RunGroup::takeStepsFor(double simulatedSeconds) {
  if (paused_) return 0;
  if (simulatedSeconds > 0.0 && std::isfinite(simulatedSeconds)) accumulator_ += simulatedSeconds;
  // A hair over the quotient: frames of 1/25 s at dt = 1/60 s sum to 2.9999999… steps after
  // three frames where 3 are meant; a step taken 1e-9 of itself early is no error to see.
  constexpr double kRoundingSlack = 1e-9;
  const int count = static_cast<int>(std::floor(accumulator_ / dt() + kRoundingSlack));
  accumulator_ = std::max(0.0, accumulator_ - count * dt());
  return count;
}

std::span<Simulation* const> RunGroup::simulations() {
  simulations_.clear();
  forEachSimulation([&](Simulation& simulation) { simulations_.push_back(&simulation); });
  return simulations_;
}

void RunGroup::setHistoryBound(std::size_t bytes, std::uint64_t ballStepsPerAnchor) {
  history_.setBound(bytes);
  history_.setBallStepsPerAnchor(ballStepsPerAnchor);
  restartHistory();
}

void RunGroup::reloadBackends(bool all) {
  const auto refresh = [&](Simulation& simulation, const RunSpec& spec) {
    if (all || !simulation.backendFresh()) simulation.setBackend(makeBackend(spec));
  };
  for (Run& run : runs_)
    refresh(*run.simulation, run.spec);
  if (baseline_) refresh(*baseline_, runs_.front().spec);
}

void RunGroup::restartHistory(bool reload) {
  if (!keepsHistory()) return;
  // Re-stepping starts at an anchor: every backend must have just been loaded from its state
  // there, as a backend switch does (RunHistory says why a saved state is not enough).
  reloadBackends(reload);
  history_.start(simulations());
}

void RunGroup::recordHistory() {
  if (!keepsHistory()) return;
  if (!history_.record(simulations())) return restartHistory();
  if (history_.anchorDue(simulations())) {
    reloadBackends(false);
    history_.anchor(simulations());
  }
}

void RunGroup::rewindTo(std::size_t index) {
  if (!keepsHistory() || stepping_ || index >= history_.size()) return;
  history_.keepNow(simulations());
  history_.restore(index, simulations());
  accumulator_ = 0.0;
}

void RunGroup::stepBack() {
  if (!keepsHistory()) return;
  history_.keepNow(simulations());
  if (history_.position() > 0) rewindTo(history_.position() - 1);
}

}  // namespace fooball
