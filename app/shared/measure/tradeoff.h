#pragma once

#include <functional>
#include <ostream>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "fooball/scene.h"
#include "registry.h"

namespace fooball::measure {

/// The backend whose run is the reference a trajectory error is measured from: it solves every
/// collision at its exact time.
inline constexpr std::string_view kReferenceBackend = "exact";

/// One backend with some of its options set (the rest at their defaults).
struct TradeoffSetting {
  std::string backend;
  std::vector<std::string> options;  ///< "KEY=VALUE"
};

/// The settings `fooball-cli tradeoff` tries: a backend without substeps at its defaults; one
/// with an OptionRole::Substeps option at 1 … 64 substeps (its solver time step is dt/substeps),
/// times 2, 8 and 32 iterations for one with an OptionRole::Iterations option too (Box2D's
/// velocity_iterations).
std::vector<TradeoffSetting> tradeoffGrid(std::span<const BackendInfo> backends);

/// "substeps=4 velocity_iterations=8", or "defaults".
std::string settingsText(const TradeoffSetting& setting);

struct TradeoffSettings {
  /// s of simulated time each setting runs: the cost and the energy, momentum and overlap
  /// errors are taken over it.
  double duration = 2.0;
  /// s: when the balls are compared with the exact backend's. Short on purpose: a gas is
  /// chaotic, and in the `gas` preset a 1 nm nudge has grown ×5 at 0.2 s, ×110 at 0.5 s and
  /// ×36'000 at 1 s (chaosGrowth), so beyond a few tenths of a second every method looks
  /// equally wrong, whatever its step.
  double compareAt = 0.2;
  double dt = 1.0 / 60.0;  ///< s, one frame
  int timingRepeats = 3;   ///< the CPU cost is the least of this many runs
};

/// What one setting costs and gets wrong on the scene.
struct TradeoffPoint {
  TradeoffSetting setting;
  double cpuMsPerSimulatedSecond = 0.0;  ///< CPU ms (all threads) per simulated second
  /// Largest |relative energy error| over the run (relativeEnergyError, fooball/metrics.h).
  double energyError = 0.0;
  /// |P(T) − P(0) − M·g·T| relative to Σ m|v(0)|, on the scene with its walls open and no drag,
  /// where nothing but ball–ball collisions and gravity acts on the momentum.
  double momentumError = 0.0;
  double maxOverlap = 0.0;       ///< deepest overlap over the run, fraction of the smaller radius
  double trajectoryError = 0.0;  ///< m, RMS distance at compareAt from the exact run's balls
};

/// Where a tradeoff run is, for a progress line.
struct TradeoffProgress {
  const TradeoffSetting* setting = nullptr;  ///< the setting just measured
  double fraction = 0.0;                     ///< of all settings, in (0, 1]
};

/// Throws std::invalid_argument naming the first bad setting (a duration, compare time or dt
/// that is not a number > 0, too many steps).
void checkTradeoffSettings(const TradeoffSettings& settings);

/// Measures every setting on `scene` (valid), against one run of the `exact` backend. Throws
/// std::invalid_argument for bad settings. A stop request ends the run after the current
/// setting; the points measured so far are returned.
std::vector<TradeoffPoint> measureTradeoff(
    const Scene& scene, std::span<const TradeoffSetting> grid, const TradeoffSettings& settings,
    const std::function<void(const TradeoffProgress&)>& progress = {}, std::stop_token stop = {});

/// How much the scene amplifies a difference by compareAt: the largest distance between the
/// balls of two exact runs of `scene`, one with ball 0 nudged by 1 nm, over that 1 nm. Near 1,
/// a trajectory error measures the method; in the thousands, mostly the chaos.
double chaosGrowth(const Scene& scene, const TradeoffSettings& settings);

/// The columns of `tradeoff --csv`: DESIGN.md's three, the errors, and whether the point is on
/// its backend's Pareto front of cost against trajectory error and against energy error.
inline constexpr std::string_view kTradeoffCsvHeader =
    "backend,settings,cpu_ms_per_sim_s,energy_error,momentum_error,max_overlap,"
    "trajectory_error_m,on_trajectory_front,on_energy_front";

void writeTradeoffCsv(std::ostream& out, std::span<const TradeoffPoint> points);

/// Which points are on their backend's front, for `error` (e.g. &TradeoffPoint::energyError).
std::vector<bool> onFront(std::span<const TradeoffPoint> points, double TradeoffPoint::*error);

}  // namespace fooball::measure
