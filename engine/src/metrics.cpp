#include "fooball/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "overlap_search.h"

namespace fooball {

StateSums sumState(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                   std::span<const double> masses, Vec2 gravity) {
  StateSums sums;
  double totalMass = 0.0;
  Vec2 massMoment;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    const double m = masses[i];
    sums.kineticEnergy += 0.5 * m * lengthSquared(velocities[i]);
    sums.potentialEnergy -= m * dot(gravity, positions[i]);
    sums.momentum += m * velocities[i];
    massMoment += m * positions[i];
    totalMass += m;
  }
  if (totalMass > 0.0) sums.centreOfMass = massMoment / totalMass;
  return sums;
}

namespace {

double wallOverlap(Vec2 p, double r, const Box& box, const Walls& walls) {
  double depth = 0.0;
  if (walls.left) depth = std::max(depth, r - p.x);
  if (walls.right) depth = std::max(depth, p.x + r - box.width);
  if (walls.bottom) depth = std::max(depth, r - p.y);
  if (walls.top) depth = std::max(depth, p.y + r - box.height);
  return depth / r;
}

}  // namespace

double maxOverlap(std::span<const Vec2> positions, std::span<const double> radii, const Box& box,
                  const Walls& walls) {
  if (positions.empty()) return 0.0;
  double deepest = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i)
    deepest = std::max(deepest, wallOverlap(positions[i], radii[i], box, walls));
  return std::max(deepest, deepestPairOverlap(positions, radii));
}

std::size_t countEscaped(std::span<const Vec2> positions, const Box& box) {
  return static_cast<std::size_t>(std::count_if(positions.begin(), positions.end(), [&](Vec2 p) {
    return !(p.x >= 0.0 && p.x <= box.width && p.y >= 0.0 && p.y <= box.height);
  }));
}

double relativeEnergyError(double energyResidual, double initialEnergy) {
  const double scale = std::abs(initialEnergy);
  if (scale == 0.0 || !std::isfinite(scale)) return std::numeric_limits<double>::quiet_NaN();
  return energyResidual / scale;
}

}  // namespace fooball
