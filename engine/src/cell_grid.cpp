#include "fooball/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace fooball {

void CellGrid::build(std::span<const Vec2> points, double width, double height,
                     double minCellSize) {
  buildFrom(
      points.size(), [&](std::size_t i) { return points[i]; }, width, height, minCellSize);
}

void CellGrid::build(std::span<const double> xs, std::span<const double> ys, double width,
                     double height, double minCellSize) {
  buildFrom(
      xs.size(),
      [&](std::size_t i) {
        return Vec2{xs[i], ys[i]};
      },
      width, height, minCellSize);
}

template <class PositionOf>
void CellGrid::buildFrom(std::size_t count, PositionOf positionOf, double width, double height,
                         double minCellSize) {
  // Cells no smaller than asked, and no more cells than ~2 per point: beyond that, empty cells
  // cost more to scan than the pairs they save.
  const double maxCells = std::max(16.0, 2.0 * static_cast<double>(count));
  cellSize_ = std::max({minCellSize, std::sqrt(width * height / maxCells), 1e-9});
  columns_ = std::max(1, static_cast<int>(std::min(width / cellSize_, maxCells)));
  rows_ = std::max(1, static_cast<int>(std::min(height / cellSize_, maxCells)));
  inverseCellSize_ = 1.0 / cellSize_;

  const std::size_t cellCount = static_cast<std::size_t>(columns_) * rows_;
  cellStart_.assign(cellCount + 1, 0);
  cellOfPoint_.resize(count);
  order_.resize(count);

  // Counting sort: count per cell, prefix sums, then scatter.
  for (std::size_t i = 0; i < count; ++i) {
    cellOfPoint_[i] = static_cast<std::uint32_t>(cellOf(positionOf(i)));
    ++cellStart_[cellOfPoint_[i] + 1];
  }
  for (std::size_t cell = 0; cell < cellCount; ++cell)
    cellStart_[cell + 1] += cellStart_[cell];
  for (std::size_t i = 0; i < count; ++i) {
    order_[cellStart_[cellOfPoint_[i]]++] = static_cast<std::uint32_t>(i);
  }
  // The scatter advanced each start to the next cell's; shift back.
  for (std::size_t cell = cellCount; cell > 0; --cell)
    cellStart_[cell] = cellStart_[cell - 1];
  cellStart_[0] = 0;
}

int CellGrid::cellOf(Vec2 p) const {
  // Clamp: points outside the rectangle (walls off) live in the border cells. The comparison
  // form also sends NaN to cell 0 instead of undefined behaviour in the cast.
  const double fx = p.x * inverseCellSize_;
  const double fy = p.y * inverseCellSize_;
  const int column = fx > 0.0 ? (fx < columns_ ? static_cast<int>(fx) : columns_ - 1) : 0;
  const int row = fy > 0.0 ? (fy < rows_ ? static_cast<int>(fy) : rows_ - 1) : 0;
  return row * columns_ + column;
}

}  // namespace fooball
