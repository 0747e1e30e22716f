#include "cell_grid.h"

#include <algorithm>
#include <cmath>

namespace fooball::xpbd {

namespace {

/// Exact sizes, released when a scene shrinks: memory follows the scene.
void resizeExactly(std::vector<std::uint32_t>& array, std::size_t size) {
  array.resize(size);
  array.shrink_to_fit();
}

}  // namespace

void CellGrid::layout(std::size_t ballCount, double width, double height, double minCellSize) {
  const double maxCells = std::max(16.0, kCellsPerBall * static_cast<double>(ballCount));
  const double cellSize = std::max({minCellSize, std::sqrt(width * height / maxCells), 1e-9});
  columns_ = std::max(1, static_cast<int>(std::min(width / cellSize, maxCells)));
  rows_ = std::max(1, static_cast<int>(std::min(height / cellSize, maxCells)));
  inverseCellSize_ = 1.0 / cellSize;
  oversizedRadius_ = 0.5 * cellSize;
  const std::size_t cellCount = static_cast<std::size_t>(columns_) * rows_ + 1;
  resizeExactly(cellStart_, cellCount + 1);
  resizeExactly(cellOfSlot_, ballCount);
  resizeExactly(sortedSlots_, ballCount);
}

void CellGrid::build(std::span<const Particle> particles) {
  const auto oversized = static_cast<std::uint32_t>(oversizedCell());
  std::fill(cellStart_.begin(), cellStart_.end(), 0u);
  // Count into cellStart_[cell + 1], so the prefix sum leaves each cell's start in place.
  for (std::size_t slot = 0; slot < particles.size(); ++slot) {
    const Particle& p = particles[slot];
    const std::uint32_t cell = p.radius > oversizedRadius_ ? oversized : cellAt(p.x, p.y);
    cellOfSlot_[slot] = cell;
    ++cellStart_[cell + 1];
  }
  for (std::size_t cell = 1; cell < cellStart_.size(); ++cell)
    cellStart_[cell] += cellStart_[cell - 1];
  // Scatter with each start as the cell's cursor, then shift the cursors back by one cell.
  for (std::uint32_t slot = 0; slot < particles.size(); ++slot)
    sortedSlots_[cellStart_[cellOfSlot_[slot]]++] = slot;
  for (std::size_t cell = cellStart_.size() - 1; cell > 0; --cell)
    cellStart_[cell] = cellStart_[cell - 1];
  cellStart_[0] = 0;
}

std::size_t CellGrid::memoryBytes() const {
  return (cellOfSlot_.capacity() + sortedSlots_.capacity() + cellStart_.capacity()) *
         sizeof(std::uint32_t);
}

}  // namespace fooball::xpbd
