#pragma once

#include <cstdint>
#include <vector>

#include "axis.h"
#include "fooball/vec2.h"
#include "linked_lists.h"

namespace fooball::exact {

/// Cell lists for event-driven motion. Cells are at least one largest diameter wide, so a ball
/// can only touch balls in its own and the 8 adjacent cells; a ball's cell changes only at its
/// cell-crossing events, and the lists are linked so that a move costs O(1). The border cells
/// reach to infinity, so a ball that leaves the box through a wall that is off still has a cell
/// and the neighbour rule still holds. The grid is framed by a ring of cells that stay empty, so
/// visiting the 3×3 block around any cell needs no clipping.
class EventCells {
 public:
  static constexpr std::uint32_t kNone = kEndOfList;

  /// Lays out cells of side ≥ minCellSize (m) over [0,width]×[0,height], no more than about
  /// 4 per ball so sparse scenes do not pay for empty cells, and empties them.
  void configure(double width, double height, double minCellSize, std::size_t ballCount);

  /// Puts the ball into the cell containing `position` (clamped to the border cells).
  void insert(std::uint32_t ball, Vec2 position);

  /// Moves the ball to the neighbouring cell across `side` of its cell.
  void cross(std::uint32_t ball, Side side);

  int columnOf(std::uint32_t ball) const { return members_[ball].column; }
  int rowOf(std::uint32_t ball) const { return members_[ball].row; }
  int cellCount(int axis) const { return axis == 0 ? columns_ : rows_; }

  /// m, the lower and upper face of cell `index` along `axis`; callers skip the faces of border
  /// cells that face outwards (index 0 lower, last index upper), which lie at infinity.
  double lowerFace(int axis, int index) const { return index * cellSide_[axis]; }
  double upperFace(int axis, int index) const { return (index + 1) * cellSide_[axis]; }

  /// Calls visit(other) for every ball in the 3×3 block of cells around the ball, itself excluded.
  template <typename Visit>
  void forEachNeighbour(std::uint32_t ball, Visit&& visit) const {
    const Membership& member = members_[ball];
    forEachIn(member.column - 1, member.column + 1, member.row - 1, member.row + 1, ball, visit);
  }

  /// After cross(ball, side): calls visit(other) for every ball in the 3 cells that have just
  /// become adjacent, the row or column beyond the ball's new cell in the direction it moved.
  template <typename Visit>
  void forEachNewNeighbour(std::uint32_t ball, Side side, Visit&& visit) const {
    const Membership& member = members_[ball];
    const int step = isLowerSide(side) ? -1 : 1;
    if (axisOf(side) == 0) {
      const int column = member.column + step;
      forEachIn(column, column, member.row - 1, member.row + 1, ball, visit);
    } else {
      const int row = member.row + step;
      forEachIn(member.column - 1, member.column + 1, row, row, ball, visit);
    }
  }

 private:
  /// Visits the balls in columns [firstColumn, lastColumn] × rows [firstRow, lastRow] (at most
  /// 3 × 3), each in [−1, count] (the frame), except `self`. The non-empty lists are gathered
  /// first without a jump per cell: most cells are empty or hold one ball, so testing each in
  /// turn would be a coin-flip branch.
  template <typename Visit>
  void forEachIn(int firstColumn, int lastColumn, int firstRow, int lastRow, std::uint32_t self,
                 Visit& visit) const {
    std::uint32_t lists[9];
    std::size_t listCount = 0;
    for (int y = firstRow; y <= lastRow; ++y) {
      for (std::size_t cell = cellIndex(firstColumn, y), last = cellIndex(lastColumn, y);
           cell <= last; ++cell) {
        const std::uint32_t head = head_[cell];
        lists[listCount] = head;
        listCount += head != kNone ? 1 : 0;
      }
    }
    for (std::size_t list = 0; list < listCount; ++list) {
      for (std::uint32_t other = lists[list]; other != kNone; other = members_[other].next) {
        if (other != self) visit(other);
      }
    }
  }

  /// Index into head_ of the cell in `column` and `row`, each in [−1, count].
  std::size_t cellIndex(int column, int row) const {
    return static_cast<std::size_t>(row + 1) * static_cast<std::size_t>(columns_ + 2) +
           static_cast<std::size_t>(column + 1);
  }

  void link(std::uint32_t ball);
  void unlink(std::uint32_t ball);

  int columns_ = 1;
  int rows_ = 1;
  double cellSide_[2] = {1.0, 1.0};  ///< m, width and height of a cell
  std::vector<std::uint32_t> head_;  ///< per cell (frame included), its first ball
  /// A ball's cell and its links in that cell's list, together in 16 bytes: moving a ball
  /// touches one record instead of four arrays.
  struct Membership {
    std::uint32_t next = kNone;
    std::uint32_t previous = kNone;
    int column = 0;
    int row = 0;
  };
  std::vector<Membership> members_;  ///< per ball
};

}  // namespace fooball::exact
