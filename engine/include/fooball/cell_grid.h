#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fooball/vec2.h"

namespace fooball {

/// A uniform grid over a rectangle, filled by counting sort: O(N) to build, no allocation once
/// the buffers have grown. Points outside the rectangle are clamped into the border cells, so
/// every point is found. Used as broadphase (cell size ≥ the largest diameter: a ball's
/// neighbours are in its own and the 8 adjacent cells) and for reordering balls by cell.
class CellGrid {
 public:
  /// Sorts `points` into cells of side ≥ `minCellSize` (m) covering [0,width] × [0,height].
  /// The cell count is capped near the point count, so sparse scenes do not pay for empty cells.
  void build(std::span<const Vec2> points, double width, double height, double minCellSize);
  /// The same for points stored as separate coordinate arrays (structure of arrays).
  void build(std::span<const double> xs, std::span<const double> ys, double width, double height,
             double minCellSize);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cellSize() const { return cellSize_; }

  int cellOf(Vec2 p) const;
  int cellColumn(int cell) const { return cell % columns_; }
  int cellRow(int cell) const { return cell / columns_; }

  /// Indices (into the built points) in cell `cell`.
  std::span<const std::uint32_t> pointsIn(int cell) const {
    return {order_.data() + cellStart_[cell], order_.data() + cellStart_[cell + 1]};
  }
  /// All point indices sorted by cell: a locality-friendly order.
  std::span<const std::uint32_t> order() const { return order_; }

  /// Calls visit(a, b) once for every unordered pair of points in the same or adjacent cells,
  /// cell by cell in row-major order (deterministic). With cells a diameter wide, this is every
  /// pair of balls that can touch.
  template <class Visit>
  void forEachNearbyPair(Visit&& visit) const {
    // The cell itself and four of its eight neighbours (right, and the three above), so each
    // pair of cells is visited once.
    constexpr int kNeighbourOffsets[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    for (int row = 0; row < rows_; ++row) {
      for (int column = 0; column < columns_; ++column) {
        const auto here = pointsIn(row * columns_ + column);
        for (std::size_t i = 0; i < here.size(); ++i) {
          for (std::size_t j = i + 1; j < here.size(); ++j)
            visit(here[i], here[j]);
        }
        for (const auto& offset : kNeighbourOffsets) {
          const int c = column + offset[0];
          const int r = row + offset[1];
          if (c < 0 || c >= columns_ || r >= rows_) continue;
          const auto there = pointsIn(r * columns_ + c);
          for (const std::uint32_t a : here) {
            for (const std::uint32_t b : there)
              visit(a, b);
          }
        }
      }
    }
  }

 private:
  template <class PositionOf>
  void buildFrom(std::size_t count, PositionOf positionOf, double width, double height,
                 double minCellSize);

  int columns_ = 1;
  int rows_ = 1;
  double cellSize_ = 1.0;
  double inverseCellSize_ = 1.0;
  std::vector<std::uint32_t> cellStart_;  ///< columns·rows + 1 prefix sums
  std::vector<std::uint32_t> cellOfPoint_;
  std::vector<std::uint32_t> order_;
};

}  // namespace fooball
