#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fooball::plots {

/// One run of `fooball-cli compare` sampled against time.
struct CompareCurve {
  std::string label;                   ///< the run's spec, or "baseline"
  bool baseline = false;               ///< the chaos baseline: drawn grey and dashed
  std::vector<double> times;           ///< s
  std::vector<double> rmsDivergence;   ///< m, RMS distance from run 0 over balls of one index
  std::vector<double> energyResidual;  ///< J, Metrics::energyResidual of the run itself
  double initialEnergy = 0.0;          ///< J, the run's E(0) (Metrics::initialEnergy)
};

/// What `compare --chart` draws.
struct CompareChart {
  std::string title;                 ///< e.g. "'Ideal gas' (300 balls, dt 0.0167 s)"
  double duration = 0.0;             ///< s, the x range
  double departThreshold = 0.0;      ///< m, drawn as a line on the divergence panel (0: none)
  std::vector<CompareCurve> curves;  ///< run 0 first, the baseline (if any) last
};

/// Two panels against time: the RMS divergence from run 0 (log axis, so chaos' exponential
/// growth is a straight line; zeros are left out) and the energy residual (symmetric log axis),
/// as the relative energy error (fooball/metrics.h) so every scene reads the same way, or in J
/// where a run's E(0) is 0, one colour per run, the baseline grey and dashed. Throws
/// std::runtime_error when the PNG cannot be written.
void saveCompareChart(const CompareChart& chart, const std::filesystem::path& path);

}  // namespace fooball::plots
