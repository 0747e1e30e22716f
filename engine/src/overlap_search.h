#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "fooball/scene.h"

namespace fooball {

struct DeepOverlap {
  std::size_t first = 0;       ///< the lower index
  std::size_t second = 0;      ///< the higher index
  double depthFraction = 0.0;  ///< overlap depth / the smaller radius
};

/// A pair of balls overlapping by more than `slop` × the smaller radius, or nothing.
///
/// O(N log N) for any mix of sizes and positions, as a loader of million-ball files needs:
/// balls are sorted into grids, one per power-of-two size, with cells at least a diameter wide,
/// so a cell never holds more than a handful of balls that do not overlap, whether the sizes are
/// mixed, the balls clustered or the box huge. (One grid sized for the biggest ball would put
/// every small ball of a gas around one big ball into the same few cells: quadratic.) Sorting,
/// not hashing, keeps neighbouring cells close in memory. Deterministic: the same balls give the
/// same pair.
std::optional<DeepOverlap> findDeepOverlap(std::span<const BallDef> balls, double slop);

/// The deepest overlapping pair (on a tie, the one with the lowest indices), or nothing when no
/// two balls overlap. The grids of findDeepOverlap, searched to the end: O(N log N) while cells
/// hold a handful of balls, as in any state a simulation saves.
std::optional<DeepOverlap> deepestOverlap(std::span<const BallDef> balls);

/// The deepest overlap of two balls (radii in m), as a fraction of the smaller radius; 0 when
/// none overlap. The grids of findDeepOverlap, so a few big balls among many small ones cost no
/// more than equal balls.
double deepestPairOverlap(std::span<const Vec2> positions, std::span<const double> radii);

}  // namespace fooball
