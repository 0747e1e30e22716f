#include "fooball/limit_check.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "message_text.h"

namespace fooball {

namespace {

/// s, the solver's own step: dt over the substeps where the backend has them. Box2D's
/// auto_substeps may raise its count for fast balls; the stated count is the conservative one.
double solverStep(const Simulation& run) {
  const OptionSet& options = run.backend().options();
  const OptionSpec* substeps = options.withRole(OptionRole::Substeps);
  return substeps ? run.dt() / options.value(substeps->name) : run.dt();
}

/// Whether gravity presses balls against a wall that is on, where a pile can rest.
bool wallUnderGravity(const WorldSettings& world) {
  const Vec2 g = world.gravity;
  const Walls& walls = world.walls;
  return (g.y < 0.0 && walls.bottom) || (g.y > 0.0 && walls.top) || (g.x < 0.0 && walls.left) ||
         (g.x > 0.0 && walls.right);
}

void checkBoundary(std::vector<CrossedLimit>& crossed, MethodLimit limit, double value,
                   const std::optional<MeasuredBoundary>& boundary) {
  if (boundary && value >= boundary->failsFrom)
    crossed.push_back({limit, value, boundary->failsFrom, boundary->passesUpTo});
}

}  // namespace

LimitNumbers measureLimitNumbers(const Simulation& run) {
  LimitNumbers numbers;
  const auto velocities = run.velocities();
  const auto radii = run.radii();
  if (radii.empty()) return numbers;
  // The velocities' bounding box: its diagonal bounds every pair's closing speed, and balls
  // that move together (a falling crowd) do not add up as their speeds would.
  Vec2 lowest = velocities.front();
  Vec2 highest = velocities.front();
  double smallestRadius = radii.front();
  double area = 0.0;  // m²
  for (std::size_t i = 0; i < radii.size(); ++i) {
    lowest = {std::min(lowest.x, velocities[i].x), std::min(lowest.y, velocities[i].y)};
    highest = {std::max(highest.x, velocities[i].x), std::max(highest.y, velocities[i].y)};
    smallestRadius = std::min(smallestRadius, radii[i]);
    area += std::numbers::pi * radii[i] * radii[i];
  }
  const double h = solverStep(run);
  const WorldSettings& world = run.world();
  numbers.closingPerSolverStep = length(highest - lowest) * h / smallestRadius;
  if (world.ballCollisions && wallUnderGravity(world))
    numbers.pileSinkPerSolverStep = length(world.gravity) * h * h / smallestRadius;
  numbers.packingFraction = area / (run.box().width * run.box().height);
  numbers.relativeEnergyError = relativeEnergyError(run.metrics(GeometryChecks::Skip));
  return numbers;
}

std::vector<CrossedLimit> crossedLimits(const LimitNumbers& numbers, const MethodLimits& limits) {
  std::vector<CrossedLimit> crossed;
  checkBoundary(crossed, MethodLimit::Tunnelling, numbers.closingPerSolverStep, limits.tunnelling);
  checkBoundary(crossed, MethodLimit::RestingPile, numbers.pileSinkPerSolverStep,
                limits.restingPile);
  checkBoundary(crossed, MethodLimit::Packing, numbers.packingFraction, limits.packing);
  // NaN (no E(0) to be relative to) is not beyond the limit.
  const double error = std::abs(numbers.relativeEnergyError);
  if (error > kEnergyErrorLimit) {
    crossed.push_back({MethodLimit::EnergyError, error, kEnergyErrorLimit, 0.0});
  }
  return crossed;
}

std::vector<CrossedLimit> crossedLimits(const Simulation& run, const MethodLimits& limits) {
  return crossedLimits(measureLimitNumbers(run), limits);
}

std::string limitName(MethodLimit limit) {
  switch (limit) {
    case MethodLimit::Tunnelling:
      return "tunnelling";
    case MethodLimit::RestingPile:
      return "resting pile";
    case MethodLimit::Packing:
      return "dense packing";
    case MethodLimit::EnergyError:
      return "energy error";
  }
  return {};
}

namespace {

/// What the number is called in the notice and the docs.
std::string numberName(MethodLimit limit) {
  switch (limit) {
    case MethodLimit::Tunnelling:
      return "v·h/r";
    case MethodLimit::RestingPile:
      return "g·h²/r";
    case MethodLimit::Packing:
      return "packing";
    case MethodLimit::EnergyError:
      return "|residual|/|E(0)|";
  }
  return {};
}

std::string measured(const CrossedLimit& crossed) {
  const std::string fails = roundedNumberText(crossed.boundary);
  if (crossed.passesUpTo == 0.0) return "measured to fail from " + fails + ", the lowest tried";
  return "measured to hold up to " + roundedNumberText(crossed.passesUpTo) + " and to fail from " +
         fails;
}

}  // namespace

std::string methodLimitNotice(const std::vector<CrossedLimit>& crossed) {
  if (crossed.empty()) return {};
  std::string text = "beyond the method's measured limits (docs/accuracy.md):";
  for (std::size_t i = 0; i < crossed.size(); ++i) {
    const CrossedLimit& limit = crossed[i];
    text += (i == 0 ? " " : ", ") + limitName(limit.limit) + " (" + numberName(limit.limit) +
            " = " + roundedNumberText(limit.value) +
            (limit.limit == MethodLimit::EnergyError ? " > " : ", fails from ") +
            roundedNumberText(limit.boundary) + ")";
  }
  return text;
}

std::string limitExplanation(const CrossedLimit& crossed) {
  const std::string value = roundedNumberText(crossed.value);
  switch (crossed.limit) {
    case MethodLimit::Tunnelling:
      return "Tunnelling: the fastest balls close " + value +
             " radii of the smallest ball per solver step (v·h/r, h = dt/substeps); this method "
             "was " +
             measured(crossed) +
             ", beyond which a ball can pass through another (docs/accuracy.md, \"Tunnelling\"). "
             "More substeps or a smaller dt lower the number in proportion; an event-driven "
             "method computes every hit's time and never tunnels.";
    case MethodLimit::RestingPile:
      return "Resting pile: gravity sinks a resting ball " + value +
             " of the smallest radius into the one below per solver step (g·h²/r); this method "
             "was " +
             measured(crossed) +
             ", beyond which a pile boils, gaining energy, or its balls sink into each other "
             "(docs/accuracy.md, \"Resting pile under strong gravity\"). More substeps lower the "
             "number with their square; so does a smaller dt or less gravity.";
    case MethodLimit::Packing:
      return "Dense packing: the balls cover " + value + " of the box; this method was " +
             measured(crossed) +
             " (0.1 m balls), beyond which balls overlap by more than 0.1 r or the energy drifts "
             "(docs/accuracy.md, \"Dense packing\"). Fewer balls, more substeps or an "
             "event-driven method.";
    case MethodLimit::EnergyError:
      return "Energy error: the method's own error (the energy budget's residual) is " + value +
             " of the energy the run started with, more than " +
             roundedNumberText(crossed.boundary) +
             ", whether or not a mapped limit explains it: its trajectory is not to be trusted. "
             "More substeps or a smaller dt, and compare with another method.";
  }
  return {};
}

}  // namespace fooball
