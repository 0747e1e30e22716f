#include "fooball/gas_statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fooball/run_group.h"
#include "fooball/simulation.h"

namespace fooball {

TheoryCaveats theoryCaveats(const WorldSettings& world, const Interactions& interactions) {
  TheoryCaveats caveats;
  caveats.gravity = world.gravity.x != 0.0 || world.gravity.y != 0.0;
  caveats.drag = world.airResistance != 0.0;
  caveats.noBallCollisions = !world.ballCollisions;
  caveats.openWalls = !world.walls.allOn();
  caveats.attractors = !interactions.attractors().empty();
  return caveats;
}

double speedToShow(const Simulation& run) {
  const std::span<const double> masses = run.masses();
  if (masses.empty()) return 0.0;
  double fastest = 0.0;  // m/s
  for (const Vec2 v : run.velocities())
    fastest = std::max(fastest, length(v));  // NaN is never the larger
  const double lightest = *std::min_element(masses.begin(), masses.end());
  const double kT = kineticTemperature(masses, run.velocities());
  return std::min(fastest, kTailWidths * std::sqrt(kT / lightest));
}

std::size_t speedBins(std::size_t balls) {
  const double rice = 2.0 * std::cbrt(static_cast<double>(balls));
  return static_cast<std::size_t>(std::clamp(std::lround(rice), 10L, 60L));
}

RunGasStatistics measureGas(const Simulation& run, GasWindow& window, std::size_t bins,
                            double range, std::vector<double>& scratch) {
  const BackendCounters counters = run.counters();
  window.add(run.time(), counters.wallImpulse, counters.ballCollisions);

  RunGasStatistics gas;
  gas.time = run.time();
  gas.balls = run.ballCount();
  gas.kineticTemperature = kineticTemperature(run.masses(), run.velocities());
  gas.histogram = speedHistogram(run.velocities(), bins, range);
  gas.maxwellBoltzmannDistance =
      maxwellBoltzmannDistance(run.masses(), run.velocities(), gas.kineticTemperature, scratch);
  gas.windowSpan = window.span();
  gas.wallPressure = window.wallPressure(run.box(), run.world().walls);
  gas.collisionRate = window.collisionRate(gas.balls);
  gas.theory = hardDiskTheory(run.radii(), run.masses(), run.box(), gas.kineticTemperature);
  return gas;
}

GasMonitor::GasMonitor(double windowSeconds) : emptyWindow_(windowSeconds) {}

const GasMonitor::Snapshot& GasMonitor::measure(const RunGroup& group, std::size_t bins,
                                                double range) {
  if (windows_.size() != group.runCount()) windows_.assign(group.runCount(), emptyWindow_);
  latest_.runs.clear();
  for (std::size_t i = 0; i < group.runCount(); ++i)
    latest_.runs.push_back(measureGas(group.run(i), windows_[i], bins, range, scratch_));

  latest_.expectedCounts.clear();
  const RunGasStatistics& reference = latest_.runs.front();
  if (reference.balls > 0 && reference.kineticTemperature > 0.0) {
    const MaxwellBoltzmann2D curve(group.run(0).masses(), reference.kineticTemperature);
    const double width = reference.histogram.binWidth;
    for (std::size_t k = 0; k < bins; ++k) {
      latest_.expectedCounts.push_back(curve.expectedCount(
          static_cast<double>(k) * width, static_cast<double>(k + 1) * width, reference.balls));
    }
  }
  latest_.caveats = theoryCaveats(group.world(), group.interactions());
  return latest_;
}

void GasMonitor::clear() {
  for (GasWindow& window : windows_)
    window.clear();
}

}  // namespace fooball
