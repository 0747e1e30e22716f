#pragma once

#include <array>
#include <cstddef>

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
  RelativeEnergyResidual,  ///< energyResidual / |E₀|; NaN when E₀ is zero
};
inline constexpr std::size_t kQuantityCount = 8;
static_assert(static_cast<std::size_t>(Quantity::RelativeEnergyResidual) + 1 == kQuantityCount);

/// One state of one run, reduced to what the charts show.
struct ChartSample {
  double time = 0.0;  ///< s, simulated
  std::array<double, kQuantityCount> values{};

  double operator[](Quantity quantity) const { return values[static_cast<std::size_t>(quantity)]; }
  double& operator[](Quantity quantity) { return values[static_cast<std::size_t>(quantity)]; }
};

/// `initialTotalEnergy` (J) is E₀, the run's first total energy, for the relative residual.
ChartSample chartSampleFrom(const Metrics& metrics, double initialTotalEnergy);

}  // namespace fooball::gui
