#include "cell_lists.h"

#include <algorithm>
#include <cmath>

#include "exact_size.h"
#include "work_share.h"

namespace fooball::common {

void CellLists::layout(std::size_t ballCount, double width, double height, double minCellSize,
                       int workers) {
  const double maxCells = std::max(16.0, kCellsPerBall * static_cast<double>(ballCount));
  const double cellSize = std::max({minCellSize, std::sqrt(width * height / maxCells), 1e-9});
  columns_ = std::max(1, static_cast<int>(std::min(width / cellSize, maxCells)));
  rows_ = std::max(1, static_cast<int>(std::min(height / cellSize, maxCells)));
  inverseCellSize_ = 1.0 / cellSize;
  oversizedRadius_ = 0.5 * cellSize;

  // The grid's cells and the oversized balls' cell.
  const std::size_t cellCount = static_cast<std::size_t>(columns_) * rows_ + 1;
  resizeExactly(cellStart_, cellCount + 1);
  resizeExactly(cellOfSlot_, ballCount);
  resizeExactly(sortedSlots_, ballCount + kReadPastEnd);
  // The entries past the end are read (see slotsIn) and used as slots by prefetches: keep them
  // valid slots rather than those of a larger scene before.
  std::fill(sortedSlots_.begin() + static_cast<std::ptrdiff_t>(ballCount), sortedSlots_.end(), 0u);
  shares_.resize(static_cast<std::size_t>(workers));
  for (int worker = 0; worker < workers; ++worker) {
    const Share cells = shareOf(cellCount, worker, workers);
    shares_[worker] = {static_cast<std::uint32_t>(cells.begin),
                       static_cast<std::uint32_t>(cells.end), 0};
  }
  cellStart_[cellCount] = static_cast<std::uint32_t>(ballCount);
}

void CellLists::countShare(int worker) {
  CellShare& share = shares_[worker];
  std::uint32_t* count = cellStart_.data();
  std::fill(count + share.firstCell, count + share.endCell, 0u);
  const std::uint32_t shareSize = share.endCell - share.firstCell;
  std::uint32_t total = 0;
  // Every worker reads every ball's cell but counts only its own share: the balls lie nearly
  // in cell order (they are reordered by cell), so the share test is well predicted.
  for (const std::uint32_t cell : cellOfSlot_) {
    if (cell - share.firstCell < shareSize) {
      ++count[cell];
      ++total;
    }
  }
  share.ballCount = total;
}

void CellLists::sortShare(int worker, CellOrder order) {
  const CellShare& share = shares_[worker];
  // A team larger than the grid leaves some workers no cells (and the shift below assumes at
  // least one).
  if (share.endCell == share.firstCell) return;
  std::uint32_t start = 0;  // balls in the shares before this one
  for (int before = 0; before < worker; ++before)
    start += shares_[before].ballCount;

  // Counts to starts, then scatter with each start as the cell's cursor.
  std::uint32_t* cursor = cellStart_.data();
  for (std::uint32_t cell = share.firstCell; cell < share.endCell; ++cell) {
    const std::uint32_t count = cursor[cell];
    cursor[cell] = start;
    start += count;
  }
  const std::uint32_t shareSize = share.endCell - share.firstCell;
  const auto scatter = [&](std::uint32_t slot) {
    const std::uint32_t cell = cellOfSlot_[slot];
    if (cell - share.firstCell < shareSize) sortedSlots_[cursor[cell]++] = slot;
  };
  const auto count = static_cast<std::uint32_t>(cellOfSlot_.size());
  if (order == CellOrder::FromLowerLeft) {
    for (std::uint32_t slot = 0; slot < count; ++slot)
      scatter(slot);
  } else {
    for (std::uint32_t slot = count; slot-- > 0;)
      scatter(slot);
  }
  // Each cursor stopped at the next cell's start: shift back by one cell.
  for (std::uint32_t cell = share.endCell - 1; cell > share.firstCell; --cell)
    cursor[cell] = cursor[cell - 1];
  cursor[share.firstCell] = start - share.ballCount;
}

std::size_t CellLists::memoryBytes() const {
  return (cellOfSlot_.capacity() + sortedSlots_.capacity() + cellStart_.capacity()) *
             sizeof(std::uint32_t) +
         shares_.capacity() * sizeof(CellShare);
}

}  // namespace fooball::common
