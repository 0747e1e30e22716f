#include "chart_sample.h"

#include <cmath>
#include <limits>

namespace fooball::gui {

ChartSample chartSampleFrom(const Metrics& metrics, const Divergence& fromRunZero,
                            double initialTotalEnergy) {
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
  // A relative error has no meaning against a zero reference; NaN leaves a gap in the chart.
  sample[Quantity::RelativeEnergyResidual] =
      initialTotalEnergy != 0.0 ? metrics.energyResidual / std::abs(initialTotalEnergy)
                                : std::numeric_limits<double>::quiet_NaN();
  sample[Quantity::RmsPositionDifference] = fromRunZero.rmsPositionDifference;
  sample[Quantity::MaxPositionDifference] = fromRunZero.maxPositionDifference;
  return sample;
}

}  // namespace fooball::gui
