#pragma once

#include <array>
#include <cstddef>

#include "fooball/divergence.h"
#include "fooball/metrics.h"

namespace fooball::gui {

/// The quantities the chart panel plots, one value each per sample.
enum class Quantity : std::size_t {
  MomentumX,               ///< N·s
  MomentumY,               ///< N·s
  MomentumMagnitude,       ///< N·s, |Σ m v|
  KineticEnergy,           ///< J
  PotentialEnergy,         ///< J
  TotalEnergy,             ///< J
  EnergyResidual,          ///< J, Metrics::energyResidual: the method's own error
  RelativeEnergyResidual,  ///< relativeEnergyError (fooball/metrics.h): residual / |E(0)|
  RmsPositionDifference,   ///< m, Divergence::rmsPositionDifference from run 0
  MaxPositionDifference,   ///< m, Divergence::maxPositionDifference from run 0
};
inline constexpr std::size_t kQuantityCount = 10;
static_assert(static_cast<std::size_t>(Quantity::MaxPositionDifference) + 1 == kQuantityCount);

/// One state of one run, reduced to what the charts show.
struct ChartSample {
  double time = 0.0;  ///< s, simulated
  std::array<double, kQuantityCount> values{};

  double operator[](Quantity quantity) const { return values[static_cast<std::size_t>(quantity)]; }
  double& operator[](Quantity quantity) { return values[static_cast<std::size_t>(quantity)]; }
};

/// `fromRunZero` is the run's divergence from run 0 at the same time (zero for run 0 itself).
ChartSample chartSampleFrom(const Metrics& metrics, const Divergence& fromRunZero);

}  // namespace fooball::gui
