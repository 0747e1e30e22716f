#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fooball/scene.h"

namespace fooball::elastic {

/// The balls as structure of arrays: the hot loops touch only the arrays they need, and
/// balls can be reordered by cell for locality. `id[slot]` is the ball's scene index.
struct BallArrays {
  std::vector<double> x, y;    ///< m, centres
  std::vector<double> vx, vy;  ///< m/s
  std::vector<double> radius;  ///< m
  std::vector<double> mass;    ///< kg
  std::vector<std::uint32_t> id;

  std::size_t size() const { return id.size(); }
  void assign(std::span<const BallDef> balls);
  std::size_t slotOf(std::size_t sceneIndex) const;

  /// Reorders every array so that the ball in slot order[k] moves to slot k. `order` must be a
  /// permutation; `scratch` is reused storage (no allocation once grown).
  void permute(std::span<const std::uint32_t> order, std::vector<double>& scratch,
               std::vector<std::uint32_t>& idScratch);
};

}  // namespace fooball::elastic
