#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "exact/axis.h"
#include "fooball/vec2.h"

namespace fooball::exact {

/// Cell lists for event-driven motion. Cells are at least one largest diameter wide, so a ball
/// can only touch balls in its own and the 8 adjacent cells; a ball's cell changes only at its
/// cell-crossing events, and the lists are linked so that a move costs O(1). The border cells
/// reach to infinity, so a ball that leaves the box through a wall that is off still has a cell
/// and the neighbour rule still holds.
class EventCells {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  /// Lays out cells of side ≥ minCellSize (m) over [0,width]×[0,height], no more than about
  /// 4 per ball so sparse scenes do not pay for empty cells, and empties them.
  void configure(double width, double height, double minCellSize, std::size_t ballCount);

  /// Puts the ball into the cell containing `position` (clamped to the border cells).
  void insert(std::uint32_t ball, Vec2 position);

  /// Moves the ball to the neighbouring cell across `side` of its cell.
  void cross(std::uint32_t ball, Side side);

  int columnOf(std::uint32_t ball) const { return column_[ball]; }
  int rowOf(std::uint32_t ball) const { return row_[ball]; }
  int cellCount(int axis) const { return axis == 0 ? columns_ : rows_; }

  /// m, the lower and upper face of cell `index` along `axis`; callers skip the faces of border
  /// cells that face outwards (index 0 lower, last index upper), which lie at infinity.
  double lowerFace(int axis, int index) const { return index * cellSide_[axis]; }
  double upperFace(int axis, int index) const { return (index + 1) * cellSide_[axis]; }

  /// Calls visit(other) for every ball in the 3×3 block of cells around the ball, itself excluded.
  template <typename Visit>
  void forEachNeighbour(std::uint32_t ball, Visit&& visit) const {
    forEachIn(column_[ball] - 1, column_[ball] + 1, row_[ball] - 1, row_[ball] + 1, ball, visit);
  }

  /// After cross(ball, side): calls visit(other) for every ball in the 3 cells that have just
  /// become adjacent, the row or column beyond the ball's new cell in the direction it moved.
  template <typename Visit>
  void forEachNewNeighbour(std::uint32_t ball, Side side, Visit&& visit) const {
    const int step = isLowerSide(side) ? -1 : 1;
    if (axisOf(side) == 0) {
      const int column = column_[ball] + step;
      forEachIn(column, column, row_[ball] - 1, row_[ball] + 1, ball, visit);
    } else {
      const int row = row_[ball] + step;
      forEachIn(column_[ball] - 1, column_[ball] + 1, row, row, ball, visit);
    }
  }

 private:
  /// Visits the balls in columns [firstColumn, lastColumn] × rows [firstRow, lastRow], clipped
  /// to the grid, except `self`.
  template <typename Visit>
  void forEachIn(int firstColumn, int lastColumn, int firstRow, int lastRow, std::uint32_t self,
                 Visit& visit) const {
    for (int y = firstRow < 0 ? 0 : firstRow; y <= lastRow && y < rows_; ++y) {
      for (int x = firstColumn < 0 ? 0 : firstColumn; x <= lastColumn && x < columns_; ++x) {
        for (std::uint32_t other = head_[y * columns_ + x]; other != kNone; other = next_[other]) {
          if (other != self) visit(other);
        }
      }
    }
  }

  void link(std::uint32_t ball);
  void unlink(std::uint32_t ball);

  int columns_ = 1;
  int rows_ = 1;
  double cellSide_[2] = {1.0, 1.0};  ///< m, width and height of a cell
  std::vector<std::uint32_t> head_;  ///< per cell, its first ball
  std::vector<std::uint32_t> next_;  ///< per ball
  std::vector<std::uint32_t> previous_;
  std::vector<int> column_;
  std::vector<int> row_;
};

}  // namespace fooball::exact
