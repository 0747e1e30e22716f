#include "chart_sample.h"

#include <cmath>

namespace fooball::gui {

ChartSample chartSampleFrom(const Metrics& metrics, const Divergence& fromRunZero) {
  const StateSums& sums = metrics.sums;
  ChartSample sample;
  sample.time = metrics.time;
  sample[Quantity::MomentumX] = sums.momentum.x;
  sample[Quantity::MomentumY] = sums.momentum.y;
  sample[Quantity::MomentumMagnitude] = std::hypot(sums.momentum.x, sums.momentum.y);
  sample[Quantity::KineticEnergy] = sums.kineticEnergy;
  sample[Quantity::PotentialEnergy] = sums.potentialEnergy;
  sample[Quantity::TotalEnergy] = sums.totalEnergy();
  sample[Quantity::EnergyResidual] = metrics.energyResidual;
  // NaN where E(0) is zero leaves a gap in the chart.
  sample[Quantity::RelativeEnergyResidual] = relativeEnergyError(metrics);
  sample[Quantity::RmsPositionDifference] = fromRunZero.rmsPositionDifference;
  sample[Quantity::MaxPositionDifference] = fromRunZero.maxPositionDifference;
  return sample;
}

}  // namespace fooball::gui
