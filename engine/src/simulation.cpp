#include "fooball/simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fooball/ball_problem.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"

namespace fooball {

namespace {

BackendCounters operator+(const BackendCounters& a, const BackendCounters& b) {
  return {a.ballCollisions + b.ballCollisions,
          a.wallCollisions + b.wallCollisions,
          a.wallImpulse + b.wallImpulse,
          a.dragLoss + b.dragLoss,
          a.cutShortSteps + b.cutShortSteps,
          a.restEnergyChange + b.restEnergyChange,
          b.restingBalls};
}

}  // namespace

Simulation::Simulation(const Scene& scene, std::unique_ptr<Backend> backend)
    : backend_(std::move(backend)) {
  load(scene);
}

void Simulation::load(const Scene& scene, double startTime) {
  backend_->load(scene);
  adoptScene(scene);
  dt_ = scene.dt.value_or(kDefaultDt);
  timeBase_ = startTime;
  stepsSinceDtChange_ = 0;
  steps_ = 0;
  earlierBackends_ = {};
  externalWork_ = 0.0;
  interactions.forgetBalls();
  refreshState();
  initialEnergy_ = totalEnergy();
  backendFresh_ = true;
}

void Simulation::adoptScene(const Scene& scene) {
  name_ = scene.name;
  box_ = scene.box;
  world_ = scene.world;
  const std::size_t count = scene.balls.size();
  radii_.resize(count);
  masses_.resize(count);
  colors_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    radii_[i] = scene.balls[i].radius;
    masses_[i] = scene.balls[i].mass;
    colors_[i] = scene.balls[i].color;
  }
  positions_.resize(count);
  velocities_.resize(count);
  forces_.resize(count);
}

void Simulation::refreshState() {
  backend_->readState(positions_, velocities_);
  backendCounters_ = backend_->counters();
}

double Simulation::totalEnergy() const {
  return sumState(positions_, velocities_, masses_, world_.gravity).totalEnergy();
}

void Simulation::setBackend(std::unique_ptr<Backend> next) {
  next->load(scene());
  earlierBackends_ = earlierBackends_ + backendCounters_;
  backend_ = std::move(next);
  refreshState();
  backendFresh_ = true;
}

Scene Simulation::scene() const {
  Scene scene{name_, box_, world_, {}, {}, {}};
  if (dt_ != kDefaultDt) scene.dt = dt_;
  scene.balls.resize(ballCount());
  for (std::size_t i = 0; i < ballCount(); ++i) {
    scene.balls[i] = {positions_[i], velocities_[i], radii_[i], masses_[i], colors_[i]};
  }
  return scene;
}

Scene Simulation::savedScene(std::string_view backendName) const {
  Scene saved = scene();
  SavedFrom from{std::string(backendName), {}, time()};
  const OptionSet& options = backend_->options();
  for (const OptionSpec& spec : options.specs())
    from.options[spec.name] = options.value(spec.name);
  saved.savedFrom = std::move(from);
  return saved;
}

void Simulation::setWorld(const WorldSettings& world) {
  const double before = totalEnergy();
  backend_->setWorld(world);
  world_ = world;
  externalWork_ += totalEnergy() - before;
  backendFresh_ = false;
}

void Simulation::checkPlacement(const BallDef& ball, std::optional<std::size_t> replacing,
                                std::string_view where) const {
  validateBall(ball, box_, world_.walls, where);
  // As in the scene format: with ball collisions off, balls pass through each other freely.
  if (!world_.ballCollisions) return;
  if (const auto overlap = findOverlapProblem(ball, positions_, radii_, replacing)) {
    throw BallError(
        std::string(where) + ": would overlap balls[" + std::to_string(overlap->otherBall) + "]",
        *overlap);
  }
}

void Simulation::setBall(std::size_t index, const BallDef& ball) {
  const std::string where = "balls[" + std::to_string(index) + "]";
  if (index >= ballCount()) {
    throw SceneError(where + ": no such ball (the scene has " + std::to_string(ballCount()) + ")");
  }
  checkPlacement(ball, index, where);
  const double before = totalEnergy();
  backend_->setBall(index, ball);
  radii_[index] = ball.radius;
  masses_[index] = ball.mass;
  colors_[index] = ball.color;
  refreshState();
  externalWork_ += totalEnergy() - before;
  backendFresh_ = false;
}

void Simulation::insertBall(std::size_t index, const BallDef& ball) {
  const std::string where = "balls[" + std::to_string(index) + "]";
  if (index > ballCount()) {
    throw SceneError(where + ": no such place (the scene has " + std::to_string(ballCount()) +
                     " balls)");
  }
  checkPlacement(ball, std::nullopt, where);
  std::vector<BallDef> balls = scene().balls;
  balls.insert(balls.begin() + static_cast<std::ptrdiff_t>(index), ball);
  replaceBalls(std::move(balls));
}

void Simulation::replaceBalls(std::vector<BallDef> balls) {
  const double before = totalEnergy();
  Scene next = scene();
  next.balls = std::move(balls);
  earlierBackends_ = earlierBackends_ + backendCounters_;
  backend_->load(next);
  adoptScene(next);
  interactions.forgetBalls();
  refreshState();
  externalWork_ += totalEnergy() - before;
  backendFresh_ = true;
}

void Simulation::setDt(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("time step must be a positive number of seconds");
  }
  timeBase_ = time();
  stepsSinceDtChange_ = 0;
  dt_ = dt;
}

void BackendStep::run() {
  try {
    backend_->step(dt_, withForces_ ? std::span<const Vec2>(forces_) : std::span<const Vec2>());
  } catch (const std::exception& error) {
    failure_ = error.what();
  }
}

void Simulation::step() {
  BackendStep step = beginStep();
  step.run();
  if (!step.failure().empty()) {
    std::string why = std::move(step.failure_);
    backend_ = std::move(step.backend_);  // failed: its next step throws again
    forces_ = std::move(step.forces_);
    throw std::runtime_error(why);
  }
  finishStep(std::move(step));
}

BackendStep Simulation::beginStep() {
  const bool withForces = interactions.active();
  if (withForces) interactions.forces(balls(), dt_, forces_);
  return handOut(withForces);
}

void Simulation::replayStep(std::span<const Vec2> forces) {
  const bool withForces = !forces.empty();
  if (withForces) std::copy(forces.begin(), forces.end(), forces_.begin());
  BackendStep step = handOut(withForces);
  step.run();
  finishStep(std::move(step));
}

BackendStep Simulation::handOut(bool withForces) {
  BackendStep step;
  step.dt_ = dt_;
  step.withForces_ = withForces;
  lastStepForced_ = withForces;
  if (withForces) {
    // The contract applies J = F·dt as a kick at the start of the step, so the work is exact:
    // ΔKE = J·v + |J|²/2m.
    for (std::size_t i = 0; i < ballCount(); ++i) {
      const Vec2 impulse = dt_ * forces_[i];
      step.work_ += dot(impulse, velocities_[i] + impulse / (2.0 * masses_[i]));
    }
  }
  step.forces_ = std::move(forces_);
  step.backend_ = std::move(backend_);
  return step;
}

void Simulation::finishStep(BackendStep&& done) {
  backend_ = std::move(done.backend_);
  forces_ = std::move(done.forces_);
  externalWork_ += done.work_;
  refreshState();
  ++stepsSinceDtChange_;
  ++steps_;
  backendFresh_ = false;
}

void Simulation::abandonStep(std::unique_ptr<Backend> fresh) {
  // positions_ and velocities_ still hold the state from before the step.
  fresh->load(scene());
  earlierBackends_ = earlierBackends_ + backendCounters_;
  backend_ = std::move(fresh);
  forces_.assign(ballCount(), Vec2{});
  lastStepForced_ = false;
  refreshState();
  backendFresh_ = true;
}

std::span<const Vec2> Simulation::lastForces() const {
  return lastStepForced_ ? std::span<const Vec2>(forces_) : std::span<const Vec2>();
}

std::size_t Simulation::State::bytes() const {
  return sizeof(State) + scene.name.capacity() + scene.balls.capacity() * sizeof(BallDef);
}

Simulation::State Simulation::state() const {
  return {scene(),          dt_,
          timeBase_,        stepsSinceDtChange_,
          steps_,           earlierBackends_,
          backendCounters_, initialEnergy_,
          externalWork_};
}

void Simulation::restore(const State& state) {
  backend_->load(state.scene);
  adoptScene(state.scene);
  dt_ = state.dt;
  timeBase_ = state.timeBase;
  stepsSinceDtChange_ = state.stepsSinceDtChange;
  steps_ = state.steps;
  // The backend counts from zero again; a fresh state's backend counters are zero, so the sums
  // go on in the same order.
  earlierBackends_ = state.earlierBackends + state.backendCounters;
  initialEnergy_ = state.initialEnergy;
  externalWork_ = state.externalWork;
  lastStepForced_ = false;
  refreshState();
  backendFresh_ = true;
}

void Simulation::run(double seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) return;
  const auto count = static_cast<std::uint64_t>(std::llround(seconds / dt_));
  for (std::uint64_t i = 0; i < count; ++i)
    step();
}

BackendCounters Simulation::counters() const {
  return earlierBackends_ + backendCounters_;
}

Metrics Simulation::metrics(GeometryChecks geometry) const {
  Metrics metrics;
  metrics.time = time();
  metrics.sums = sumState(positions_, velocities_, masses_, world_.gravity);
  const BackendCounters counts = counters();
  metrics.ballCollisions = counts.ballCollisions;
  metrics.wallCollisions = counts.wallCollisions;
  metrics.wallImpulse = counts.wallImpulse;
  if (geometry == GeometryChecks::Run) {
    metrics.maxOverlap = maxOverlap(positions_, radii_, box_, world_.walls);
    metrics.escaped = countEscaped(positions_, box_);
  }
  metrics.externalWork = externalWork_;
  metrics.dragLoss = counts.dragLoss;
  metrics.restEnergyChange = counts.restEnergyChange;
  metrics.restingBalls = counts.restingBalls;
  metrics.energyResidual = metrics.sums.totalEnergy() - initialEnergy_ - externalWork_ +
                           counts.dragLoss - counts.restEnergyChange;
  metrics.initialEnergy = initialEnergy_;
  return metrics;
}

}  // namespace fooball
