#include "fooball/divergence.h"

#include <algorithm>
#include <cmath>

namespace fooball {

Divergence measureDivergence(const Simulation& reference, const Simulation& run) {
  Divergence result;
  const auto a = reference.positions();
  const auto b = run.positions();
  const std::size_t count = std::min(a.size(), b.size());
  double sumSquares = 0.0;
  double maxSquare = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double squared = lengthSquared(b[i] - a[i]);
    sumSquares += squared;
    maxSquare = std::max(maxSquare, squared);
  }
  result.maxPositionDifference = std::sqrt(maxSquare);
  result.rmsPositionDifference = count > 0 ? std::sqrt(sumSquares / double(count)) : 0.0;
  const StateSums referenceSums =
      sumState(a, reference.velocities(), reference.masses(), reference.world().gravity);
  const StateSums runSums = sumState(b, run.velocities(), run.masses(), run.world().gravity);
  result.energyDifference = runSums.totalEnergy() - referenceSums.totalEnergy();
  const double scale = std::abs(referenceSums.totalEnergy());
  result.relativeEnergyDifference = scale > 0.0 ? result.energyDifference / scale : 0.0;
  result.momentumDifference = length(runSums.momentum - referenceSums.momentum);
  return result;
}

}  // namespace fooball
