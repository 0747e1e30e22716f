#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "particles.h"

namespace fooball::xpbd {

/// The broadphase: a uniform grid over the box and the balls' slots sorted by cell (a counting
/// sort, O(N), rebuilt every substep on the predicted centres). Cells are at least one diameter
/// of the balls they hold wide, so such a ball's partners lie in its own and the 8 adjacent
/// cells. Balls too big for that ("oversized": radius above half a cell) go to one extra cell
/// after the grid's and are met by a pass of their own (pair_contacts.h): a grid sized for a few
/// big balls would crowd dozens of small ones into every cell.
///
/// Memory: 8 bytes per ball (cell and sorted slot) plus 4 per cell, with at most kCellsPerBall
/// cells per ball.
class CellGrid {
 public:
  /// Sizes the grid for `ballCount` balls in [0,width] × [0,height] (m), cells at least
  /// `minCellSize` (m) wide.
  void layout(std::size_t ballCount, double width, double height, double minCellSize);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  /// m: balls with a larger radius are oversized (half the cell size).
  double oversizedRadius() const { return oversizedRadius_; }

  /// The cell holding (x, y) (m). Points outside the box are clamped into the border cells (a
  /// wall may be off), so every ball is found; NaN goes to cell 0 rather than to undefined
  /// behaviour.
  std::uint32_t cellAt(double x, double y) const {
    const double fx = x * inverseCellSize_;
    const double fy = y * inverseCellSize_;
    const int column = fx > 0.0 ? (fx < columns_ ? static_cast<int>(fx) : columns_ - 1) : 0;
    const int row = fy > 0.0 ? (fy < rows_ ? static_cast<int>(fy) : rows_ - 1) : 0;
    return static_cast<std::uint32_t>(row * columns_ + column);
  }

  /// Sorts the balls' slots by the cell of their current centres.
  void build(std::span<const Particle> particles);

  /// Slots of the balls in cells [firstCell, endCell), ascending by cell and, within a cell, by
  /// slot: neighbouring cells of a row are one contiguous range.
  std::span<const std::uint32_t> slotsIn(int firstCell, int endCell) const {
    return {sortedSlots_.data() + cellStart_[firstCell], sortedSlots_.data() + cellStart_[endCell]};
  }
  /// Slots of the oversized balls, ascending.
  std::span<const std::uint32_t> oversizedSlots() const {
    const int cell = oversizedCell();
    return slotsIn(cell, cell + 1);
  }
  /// Every ball's slot, ascending by cell: the order the balls are moved into now and then.
  /// Left as the identity by Particles::permute, which the grid then still describes.
  std::span<std::uint32_t> sortedSlots() { return sortedSlots_; }

  std::size_t memoryBytes() const;

  /// Cells per ball at most: smaller cells leave most cells empty and cost more to scan than
  /// the pairs they save, and each costs 4 bytes.
  static constexpr double kCellsPerBall = 0.75;

 private:
  int oversizedCell() const { return columns_ * rows_; }

  int columns_ = 1;
  int rows_ = 1;
  double inverseCellSize_ = 1.0;  ///< 1/m
  double oversizedRadius_ = 0.5;  ///< m
  std::vector<std::uint32_t> cellOfSlot_;
  std::vector<std::uint32_t> sortedSlots_;
  std::vector<std::uint32_t> cellStart_;  ///< prefix sums: grid cells + the oversized cell + 1
};

}  // namespace fooball::xpbd
