#include "broadphase.h"

#include <algorithm>

namespace fooball::chipmunk_detail {

HashSizing hashSizing(std::span<const double> radii, const Box& box) {
  if (radii.empty()) return {0.1 * std::min(box.width, box.height), 1'000};
  double sum = 0.0;  // m
  for (const double radius : radii)
    sum += radius;
  const double meanDiameter = 2.0 * sum / static_cast<double>(radii.size());
  const double finest = std::max(box.width, box.height) / 4096.0;
  constexpr std::size_t kMinCells = 1'000;
  constexpr std::size_t kMaxCells = std::size_t{1} << 24;
  const std::size_t cells = std::clamp(10 * radii.size(), kMinCells, kMaxCells);
  return {std::max(meanDiameter, finest), static_cast<int>(cells)};
}

void useSpatialHash(cpSpace* space, const HashSizing& sizing) {
  cpSpaceUseSpatialHash(space, sizing.cell, sizing.cells);
}

}  // namespace fooball::chipmunk_detail
