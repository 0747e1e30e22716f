#pragma once

#include <cstddef>
#include <vector>

#include "fooball/gas_window.h"
#include "fooball/hard_disk_theory.h"
#include "fooball/interactions.h"
#include "fooball/scene.h"
#include "fooball/speed_distribution.h"

namespace fooball {

class RunGroup;
class Simulation;

/// What keeps a scene from the equilibrium the hard-disk theory describes (balls that only
/// collide, elastically, in a closed box). None set: the theory applies.
struct TheoryCaveats {
  bool gravity = false;           ///< the balls settle: density and pressure vary with height
  bool drag = false;              ///< air resistance cools the gas: no equilibrium to reach
  bool noBallCollisions = false;  ///< the balls never exchange energy: no gas, no collisions
  bool openWalls = false;         ///< balls leave through a wall that is off
  bool attractors = false;        ///< permanent attractors pull the balls together

  bool any() const { return gravity || drag || noBallCollisions || openWalls || attractors; }
};

TheoryCaveats theoryCaveats(const WorldSettings& world, const Interactions& interactions);

/// One run's gas at one moment, beside what the theory of an equilibrium hard-disk gas says for
/// the same balls at the same temperature.
struct RunGasStatistics {
  double time = 0.0;  ///< s, simulated
  std::size_t balls = 0;
  double kineticTemperature = 0.0;  ///< J per ball, ⟨½ m v²⟩
  SpeedHistogram histogram;         ///< counts plus `above` = balls
  /// Kolmogorov–Smirnov distance of the speeds from 2D Maxwell–Boltzmann at this run's own kT.
  double maxwellBoltzmannDistance = 0.0;
  double windowSpan = 0.0;     ///< s of simulated time the pressure and the rate average over
  double wallPressure = 0.0;   ///< N/m, over windowSpan (GasWindow)
  double collisionRate = 0.0;  ///< ball–ball collisions per ball per second, over windowSpan
  HardDiskTheory theory;       ///< at kineticTemperature
};

/// What a histogram of `run`'s speeds should reach (m/s) to hold every ball: the fastest
/// speed, but no more than kTailWidths thermal widths √(kT/m) of the lightest ball, so that one
/// ball flung by the slingshot does not squash the distribution into the first bins (at
/// equilibrium a speed beyond 6 widths has probability e⁻¹⁸ ≈ 10⁻⁸ per ball). 0 for no balls or
/// none moving.
double speedToShow(const Simulation& run);
inline constexpr double kTailWidths = 6.0;

/// Bins for a histogram of `balls` speeds: Rice's rule 2·N^⅓ (13 for 300 balls, 43 for 10⁴),
/// within [10, 60] so that few balls still draw a shape and many do not draw noise.
std::size_t speedBins(std::size_t balls);

/// Measures the gas of the runs of a run group on request (the statistics dock asks a few times
/// a second while it is shown): each run's speed histogram over the same bins, its kinetic
/// temperature and Kolmogorov–Smirnov distance, and its wall pressure and collision rate over
/// the last windowSeconds of simulated time, each beside the hard-disk theory. Between
/// measurements it does nothing: the window holds the counters of the measurements only, which
/// is exact (they are cumulative) however far apart the measurements are.
class GasMonitor {
 public:
  /// s of simulated time the pressure and collision rate average over: at 300 balls in the gas
  /// preset the walls take about 80 hits a second, so 5 s holds the pressure's noise to ~5%.
  static constexpr double kDefaultWindowSeconds = 5.0;

  struct Snapshot {
    std::vector<RunGasStatistics> runs;  ///< one per run, in run order
    /// Balls expected per bin by 2D Maxwell–Boltzmann at run 0's kT for run 0's balls (each
    /// run's own kT differs from it only by its energy error); empty when run 0 has no kinetic
    /// energy.
    std::vector<double> expectedCounts;
    TheoryCaveats caveats;
  };

  /// `windowSeconds` > 0, else std::invalid_argument.
  explicit GasMonitor(double windowSeconds = kDefaultWindowSeconds);

  /// Measures every run of `group` now over `bins` (≥ 1; speedBins() suggests how many) equal
  /// bins of [0, `range`) (m/s, > 0). A run restarted since starts its window afresh, and all
  /// do when the number of runs changed.
  const Snapshot& measure(const RunGroup& group, std::size_t bins, double range);
  /// Forgets the windows: after the runs were restarted or replaced.
  void clear();
  const Snapshot& latest() const { return latest_; }

 private:
  GasWindow emptyWindow_;           ///< what a run's window starts as
  std::vector<GasWindow> windows_;  ///< one per run
  std::vector<double> scratch_;     ///< scaled speeds for the KS distance; reused
  Snapshot latest_;
};

/// One run's statistics now; feeds `window` the run's time and counters first.
RunGasStatistics measureGas(const Simulation& run, GasWindow& window, std::size_t bins,
                            double range, std::vector<double>& scratch);

}  // namespace fooball
