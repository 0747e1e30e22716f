#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fooball::common {

/// Which corner of the box the grid numbers its cells from. The pair search meets the balls in
/// cell order, and each overlap it separates can push the balls it met before once more, so a
/// dense gas creeps towards the corner the numbering starts from: numbered always from the lower
/// left, 2000 balls at packing 0.5 put 0.29 of themselves in the bottom quarter of the box and
/// 0.21 in the top one (tests/elastic_backend_test.cpp). (xpbd numbers from the lower left
/// always: its projections are no such pushes.) Numbered from opposite corners on
/// alternate substeps, the pushes cancel.
enum class CellOrder : bool {
  FromLowerLeft,   ///< row 0 at y = 0, column 0 at x = 0
  FromUpperRight,  ///< row 0 at y = height, column 0 at x = width
};

/// The broadphase of the time-stepped solvers (elastic, xpbd): a uniform grid over the box, and
/// the balls' slots sorted by cell (a counting sort, O(N), rebuilt every substep). Cells are at
/// least one diameter of the balls they hold wide, so such a ball's neighbours are in its own and
/// the 8 adjacent cells. Balls too big for that ("oversized": radius above half a cell) go to one
/// extra cell after the grid's, and are met by a pass of their own (collideOversized): a grid sized
/// for a few big balls would crowd dozens of small ones into every cell.
///
/// Built in phases that a team of workers shares (one worker does them all in turn): each worker
/// computes the cells of its own balls (setCell), then counts, prefix-sums and scatters the balls
/// of its own share of the cells. The result is a pure function of the balls' cells and their
/// CellOrder — slots ascending within each cell, or descending when numbered from the upper right —
/// whatever the number of workers.
///
/// Memory: 8 bytes per ball (cell and sorted slot) plus 4 per cell, with at most
/// kCellsPerBall cells per ball.
class CellLists {
 public:
  /// Sizes the grid for `ballCount` balls in [0,width] × [0,height] (m), cells at least
  /// `minCellSize` (m) wide, and splits the cells into `workers` contiguous shares (some empty
  /// when the workers outnumber the cells).
  void layout(std::size_t ballCount, double width, double height, double minCellSize, int workers);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  /// Balls with a larger radius (m) are oversized: half the cell size.
  double oversizedRadius() const { return oversizedRadius_; }

  /// The cell holding (x, y) (m), numbered in `order`. Points outside the box are clamped into
  /// the border cells, so every ball is found; NaN goes to the first cell of the lower-left
  /// corner rather than to undefined behaviour.
  std::uint32_t cellAt(double x, double y, CellOrder order) const {
    const double fx = x * inverseCellSize_;
    const double fy = y * inverseCellSize_;
    const int column = fx > 0.0 ? (fx < columns_ ? static_cast<int>(fx) : columns_ - 1) : 0;
    const int row = fy > 0.0 ? (fy < rows_ ? static_cast<int>(fy) : rows_ - 1) : 0;
    const auto cell = static_cast<std::uint32_t>(row * columns_ + column);
    // Both row and column counted from the other end is the grid's cells counted backwards.
    return order == CellOrder::FromLowerLeft ? cell : oversizedCell() - 1 - cell;
  }
  /// The cell of a ball centred at (x, y) with radius `radius` (m), numbered in `order`: the
  /// extra cell after the grid's if it is oversized.
  std::uint32_t cellOf(double x, double y, double radius, CellOrder order) const {
    return radius > oversizedRadius_ ? oversizedCell() : cellAt(x, y, order);
  }
  void setCell(std::size_t slot, std::uint32_t cell) { cellOfSlot_[slot] = cell; }

  /// Phase 1 of a build, after every ball's setCell: counts the balls in `worker`'s share of the
  /// cells.
  void countShare(int worker);
  /// Phase 2, after every worker's countShare: sorts the slots of `worker`'s share of the cells,
  /// each cell's slots ascending, or descending for `order` FromUpperRight (the order setCell's
  /// cells were numbered in): the balls of one cell are met mirrored too, where memory keeps
  /// them in lower-left order.
  void sortShare(int worker, CellOrder order);

  /// Slots of the balls in cells [firstCell, endCell), ascending by cell: neighbouring cells in
  /// a row are contiguous here, which the pair search uses. At least kReadPastEnd more entries
  /// may be read after any range (their values mean nothing), for copies of a fixed size.
  std::span<const std::uint32_t> slotsIn(int firstCell, int endCell) const {
    return {sortedSlots_.data() + cellStart_[firstCell], sortedSlots_.data() + cellStart_[endCell]};
  }
  /// Slots of the oversized balls, ascending.
  std::span<const std::uint32_t> oversizedSlots() const {
    const int cell = static_cast<int>(oversizedCell());
    return slotsIn(cell, cell + 1);
  }
  /// Where the slots of cell `cell` begin (kReadPastEnd entries may be read from there).
  const std::uint32_t* slotsFrom(int cell) const { return sortedSlots_.data() + cellStart_[cell]; }
  /// The balls' cells by slot, free for other use between sortShare and the next setCell.
  std::span<std::uint32_t> cellsBySlot() { return cellOfSlot_; }
  /// Every ball's slot, ascending by cell.
  std::span<std::uint32_t> sortedSlots() { return {sortedSlots_.data(), cellOfSlot_.size()}; }

  static constexpr std::size_t kReadPastEnd = 16;

  std::size_t memoryBytes() const;

  /// Cells per ball at most: cells smaller than this leave most cells empty and cost more to
  /// scan than the pairs they save, and each costs 4 bytes.
  static constexpr double kCellsPerBall = 0.75;

 private:
  /// One worker's cells.
  struct CellShare {
    std::uint32_t firstCell;
    std::uint32_t endCell;
    std::uint32_t ballCount;  ///< set by countShare
  };

  std::uint32_t oversizedCell() const { return static_cast<std::uint32_t>(columns_ * rows_); }

  int columns_ = 1;
  int rows_ = 1;
  double inverseCellSize_ = 1.0;  ///< 1/m
  double oversizedRadius_ = 0.5;  ///< m
  std::vector<std::uint32_t> cellOfSlot_;
  std::vector<std::uint32_t> sortedSlots_;
  std::vector<std::uint32_t> cellStart_;  ///< prefix sums: grid cells + the oversized cell + 1
  std::vector<CellShare> shares_;
};

/// The radius (m) the grid's cells are sized for, over balls of any type with a `radius` (m):
/// the largest, unless at most one ball in `ballsPerOversized` is more than twice as big as the
/// rest — a few big balls among many small ones. Those are then left out of the grid
/// (oversized), and the cells fit the small balls.
template <class BallType>
double gridRadius(std::span<const BallType> balls, std::size_t ballsPerOversized) {
  if (balls.empty()) return 1.0;
  double largest = 0.0;
  for (const BallType& ball : balls)
    largest = std::max(largest, ball.radius);
  const std::size_t oversized = balls.size() / ballsPerOversized;  // at most
  if (oversized == 0) return largest;
  std::vector<double> radii(balls.size());
  std::transform(balls.begin(), balls.end(), radii.begin(),
                 [](const BallType& ball) { return ball.radius; });
  // The radius that `oversized` balls at most exceed.
  const auto typical = radii.end() - 1 - static_cast<std::ptrdiff_t>(oversized);
  std::nth_element(radii.begin(), typical, radii.end());
  return *typical < 0.5 * largest ? *typical : largest;
}

}  // namespace fooball::common
