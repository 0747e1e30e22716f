#include "sweep_run.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <utility>

#include "fooball/simulation.h"
#include "registry.h"

namespace fooball::failure_map {

double solverStep(const Backend& backend, double dt) {
  const OptionSpec* substeps = backend.options().withRole(OptionRole::Substeps);
  return substeps != nullptr ? dt / backend.options().value(substeps->name) : dt;
}

RunRecord runScene(const Scene& scene, std::string_view backend, double seconds, double dt,
                   EventCap cap) {
  std::unique_ptr<Backend> stepper = createBackend(backend);
  if (cap == EventCap::Finishing) stepper->capEventsToFinish();  // every point of a map must end
  Simulation simulation(scene, std::move(stepper));
  simulation.setDt(dt);
  RunRecord record;
  const auto steps = static_cast<long>(std::max(1.0, std::round(seconds / dt)));
  for (long step = 0; step < steps; ++step) {
    simulation.step();
    const Metrics metrics = simulation.metrics();
    // NaN must fail a sweep, and std::max drops a NaN in its second argument.
    record.energyDrift = std::isnan(metrics.energyResidual)
                             ? metrics.energyResidual
                             : std::max(record.energyDrift, std::abs(metrics.energyResidual));
    const double energyError = std::abs(relativeEnergyError(metrics));
    record.energyError =
        std::isnan(energyError) ? energyError : std::max(record.energyError, energyError);
    record.maxOverlap = std::max(record.maxOverlap, metrics.maxOverlap);
    record.escaped = metrics.escaped;
    if (std::isnan(record.energyDrift) || std::isnan(record.energyError)) break;
  }
  record.positions.assign(simulation.positions().begin(), simulation.positions().end());
  record.velocities.assign(simulation.velocities().begin(), simulation.velocities().end());
  return record;
}

Vec2 spreadDirection(std::size_t i) {
  // The golden angle, 2π(1 − 1/φ): consecutive directions never line up.
  const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const double angle = goldenAngle * static_cast<double>(i);
  return {std::cos(angle), std::sin(angle)};
}

std::vector<double> logGrid(double first, double last, std::size_t count) {
  std::vector<double> grid;
  const double ratio =
      std::log(last / first) / static_cast<double>(std::max<std::size_t>(1, count - 1));
  for (std::size_t i = 0; i < count; ++i)
    grid.push_back(first * std::exp(ratio * static_cast<double>(i)));
  grid.back() = last;  // exactly, not as exp(log(…)) rounds it
  return grid;
}

}  // namespace fooball::failure_map
