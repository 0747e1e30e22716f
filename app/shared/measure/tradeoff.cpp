#include "tradeoff.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fooball/metrics.h"
#include "fooball/simulation.h"
#include "pareto.h"
#include "step_timing.h"

namespace fooball::measure {

namespace {

std::unique_ptr<Backend> configured(const TradeoffSetting& setting) {
  std::unique_ptr<Backend> backend = createBackend(setting.backend);
  for (const std::string& assignment : setting.options)
    backend->setOptionFromText(assignment);
  return backend;
}

std::size_t stepsFor(double seconds, double dt) {
  return static_cast<std::size_t>(std::max(1.0, std::round(seconds / dt)));
}

/// The least CPU time (ms) of `timingRepeats` runs of the bare backend, per simulated second.
double cpuMsPerSimulatedSecond(const Scene& scene, const TradeoffSetting& setting,
                               const TradeoffSettings& settings) {
  const std::size_t steps = stepsFor(settings.duration, settings.dt);
  double least = std::numeric_limits<double>::infinity();
  for (int repeat = 0; repeat < settings.timingRepeats; ++repeat) {
    const auto backend = configured(setting);
    backend->load(scene);
    const double start = processCpuSeconds();
    for (std::size_t step = 0; step < steps; ++step)
      backend->step(settings.dt, {});
    least = std::min(least, processCpuSeconds() - start);
  }
  return 1000.0 * least / (static_cast<double>(steps) * settings.dt);
}

/// The balls' centres at compareAt.
std::vector<Vec2> positionsToCompare(const Scene& scene, std::unique_ptr<Backend> backend,
                                     const TradeoffSettings& settings) {
  Simulation simulation(scene, std::move(backend));
  simulation.setDt(settings.dt);
  for (std::size_t step = stepsFor(settings.compareAt, settings.dt); step > 0; --step)
    simulation.step();
  return {simulation.positions().begin(), simulation.positions().end()};
}

double rmsDistance(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (a.empty()) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += lengthSquared(a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

/// Energy error, deepest overlap and the positions at compareAt, from one run with metrics
/// every step.
struct AccuracyRun {
  double energyError = 0.0;
  double maxOverlap = 0.0;
  std::vector<Vec2> positions;
};

AccuracyRun accuracyRun(const Scene& scene, const TradeoffSetting& setting,
                        const TradeoffSettings& settings) {
  Simulation simulation(scene, configured(setting));
  simulation.setDt(settings.dt);
  AccuracyRun run;
  const std::size_t compareStep = stepsFor(settings.compareAt, settings.dt);
  const std::size_t steps = std::max(compareStep, stepsFor(settings.duration, settings.dt));
  for (std::size_t step = 1; step <= steps; ++step) {
    simulation.step();
    const Metrics metrics = simulation.metrics();
    // NaN (a scene without energy) stays: std::max would drop it in its second argument.
    const double energyError = std::abs(relativeEnergyError(metrics));
    run.energyError =
        std::isnan(energyError) ? energyError : std::max(run.energyError, energyError);
    run.maxOverlap = std::max(run.maxOverlap, metrics.maxOverlap);
    if (step == compareStep) {
      run.positions.assign(simulation.positions().begin(), simulation.positions().end());
    }
  }
  return run;
}

double momentumError(const Scene& scene, const TradeoffSetting& setting,
                     const TradeoffSettings& settings) {
  Scene open = scene;
  open.world.walls = {false, false, false, false};
  open.world.airResistance = 0.0;
  Simulation simulation(open, configured(setting));
  simulation.setDt(settings.dt);
  double totalMass = 0.0;
  double momentumScale = 0.0;  // Σ m|v|
  for (const BallDef& ball : open.balls) {
    totalMass += ball.mass;
    momentumScale += ball.mass * length(ball.velocity);
  }
  const Vec2 initial = simulation.metrics().sums.momentum;
  for (std::size_t step = stepsFor(settings.duration, settings.dt); step > 0; --step)
    simulation.step();
  const Vec2 expected = initial + totalMass * simulation.time() * open.world.gravity;
  const double drift = length(simulation.metrics().sums.momentum - expected);
  return momentumScale > 0.0 ? drift / momentumScale : drift;
}

}  // namespace

void checkTradeoffSettings(const TradeoffSettings& settings) {
  if (!(std::isfinite(settings.duration) && settings.duration > 0.0)) {
    throw std::invalid_argument("duration: must be a number > 0");
  }
  if (!(std::isfinite(settings.compareAt) && settings.compareAt > 0.0)) {
    throw std::invalid_argument("compare-at: must be a number > 0");
  }
  if (!(std::isfinite(settings.dt) && settings.dt > 0.0)) {
    throw std::invalid_argument("dt: must be a number > 0");
  }
  if (std::max(settings.duration, settings.compareAt) / settings.dt > 1e6) {
    throw std::invalid_argument("duration / dt: more than a million steps per run");
  }
  if (settings.timingRepeats < 1) throw std::invalid_argument("timing repeats: must be >= 1");
}

std::vector<TradeoffSetting> tradeoffGrid(std::span<const BackendInfo> backends) {
  std::vector<TradeoffSetting> grid;
  for (const BackendInfo& info : backends) {
    const auto backend = info.create();
    const OptionSpec* substeps = backend->options().withRole(OptionRole::Substeps);
    if (substeps == nullptr) {
      grid.push_back({std::string(info.name), {}});
      continue;
    }
    const OptionSpec* iterations = backend->options().withRole(OptionRole::Iterations);
    for (const int substepCount : {1, 2, 4, 8, 16, 32, 64}) {
      const std::string substepsText = substeps->name + "=" + std::to_string(substepCount);
      if (iterations == nullptr) {
        grid.push_back({std::string(info.name), {substepsText}});
        continue;
      }
      for (const int iterationCount : {2, 8, 32}) {
        grid.push_back({std::string(info.name),
                        {substepsText, iterations->name + "=" + std::to_string(iterationCount)}});
      }
    }
  }
  return grid;
}

std::string settingsText(const TradeoffSetting& setting) {
  std::string text;
  for (const std::string& option : setting.options)
    text += (text.empty() ? "" : " ") + option;
  return text.empty() ? "defaults" : text;
}

std::vector<TradeoffPoint> measureTradeoff(
    const Scene& scene, std::span<const TradeoffSetting> grid, const TradeoffSettings& settings,
    const std::function<void(const TradeoffProgress&)>& progress, std::stop_token stop) {
  checkTradeoffSettings(settings);
  for (const TradeoffSetting& setting : grid)
    configured(setting);  // unknown backends and options fail before anything runs
  const std::vector<Vec2> reference =
      positionsToCompare(scene, createBackend(kReferenceBackend), settings);
  std::vector<TradeoffPoint> points;
  for (const TradeoffSetting& setting : grid) {
    if (stop.stop_requested()) break;
    TradeoffPoint point{setting};
    point.cpuMsPerSimulatedSecond = cpuMsPerSimulatedSecond(scene, setting, settings);
    const AccuracyRun run = accuracyRun(scene, setting, settings);
    point.energyError = run.energyError;
    point.maxOverlap = run.maxOverlap;
    point.trajectoryError = rmsDistance(run.positions, reference);
    point.momentumError = momentumError(scene, setting, settings);
    points.push_back(std::move(point));
    if (progress) {
      progress({&setting, static_cast<double>(points.size()) / static_cast<double>(grid.size())});
    }
  }
  return points;
}

double chaosGrowth(const Scene& scene, const TradeoffSettings& settings) {
  if (scene.balls.empty()) return 0.0;
  constexpr double kNudge = 1e-9;  // m
  Scene nudged = scene;
  nudged.balls[0].position.x += kNudge;
  const std::vector<Vec2> a = positionsToCompare(scene, createBackend(kReferenceBackend), settings);
  const std::vector<Vec2> b =
      positionsToCompare(nudged, createBackend(kReferenceBackend), settings);
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    largest = std::max(largest, length(a[i] - b[i]));
  return largest / kNudge;
}

std::vector<bool> onFront(std::span<const TradeoffPoint> points, double TradeoffPoint::*error) {
  std::vector<bool> on(points.size(), false);
  std::vector<bool> done(points.size(), false);  // its backend's front is known
  for (std::size_t first = 0; first < points.size(); ++first) {
    if (done[first]) continue;
    std::vector<std::size_t> indices;
    std::vector<CostAndError> backendPoints;
    for (std::size_t i = first; i < points.size(); ++i) {
      if (points[i].setting.backend != points[first].setting.backend) continue;
      done[i] = true;
      indices.push_back(i);
      backendPoints.push_back({points[i].cpuMsPerSimulatedSecond, points[i].*error});
    }
    for (const std::size_t k : paretoFront(backendPoints))
      on[indices[k]] = true;
  }
  return on;
}

void writeTradeoffCsv(std::ostream& out, std::span<const TradeoffPoint> points) {
  const std::vector<bool> trajectoryFront = onFront(points, &TradeoffPoint::trajectoryError);
  const std::vector<bool> energyFront = onFront(points, &TradeoffPoint::energyError);
  out << kTradeoffCsvHeader << '\n';
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TradeoffPoint& point = points[i];
    out << point.setting.backend << ',' << settingsText(point.setting) << ','
        << point.cpuMsPerSimulatedSecond << ',' << point.energyError << ',' << point.momentumError
        << ',' << point.maxOverlap << ',' << point.trajectoryError << ','
        << (trajectoryFront[i] ? 1 : 0) << ',' << (energyFront[i] ? 1 : 0) << '\n';
  }
}

}  // namespace fooball::measure
