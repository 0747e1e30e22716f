#pragma once

#include <optional>

namespace fooball {

/// One boundary of the failure map (docs/accuracy.md), in the map's dimensionless number: the
/// last grid point measured to pass and the first measured to fail. A run at or beyond the
/// first failure is where the method was seen to fail; between the two the map cannot say, so
/// the check keeps quiet there.
struct MeasuredBoundary {
  double passesUpTo = 0.0;  ///< 0 where even the easiest point tried failed
  double failsFrom = 0.0;
};

/// Where a method was measured to stop being right, each limit in its own dimensionless number;
/// none where the method held across the map's whole grid. Each backend states its own beside
/// its registry line (BackendInfo::limits), from docs/accuracy.md's "Where" tables.
struct MethodLimits {
  /// Closing travel per solver step in radii, v·h/r (h = dt/substeps): a ball shot at a resting
  /// twin (docs/accuracy.md, "Tunnelling", the 0.05 m ball at a ball).
  std::optional<MeasuredBoundary> tunnelling;
  /// How far gravity sinks a resting ball into the one below per solver step, in radii,
  /// g·h²/r (docs/accuracy.md, "Resting pile under strong gravity").
  std::optional<MeasuredBoundary> restingPile;
  /// The fraction of the box's area the balls cover (docs/accuracy.md, "Dense packing", the
  /// r = 0.1 m column: smaller balls fail sooner, so it holds for larger ones).
  std::optional<MeasuredBoundary> packing;
};

/// g·h²/r of the map's pile sweep at gravity `g` (m/s²): 0.1 m balls, dt = 1/60 s and the
/// backend's default `substeps`, so a backend can state its measured g in the check's number.
constexpr double pileSweepNumber(double g, double substeps) {
  const double h = 1.0 / 60.0 / substeps;  // s
  return g * h * h / 0.1;
}

}  // namespace fooball
