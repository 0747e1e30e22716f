#include "pair_collisions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "pair_search.h"

namespace fooball::elastic {

namespace {

/// Bit j set when `a` overlaps the ball in slot slots[j], j < kLanes, one lane at a time.
/// Written as !(d² ≥ reach²) so a NaN counts as an overlap, as in the one-by-one test. A
/// lambda, so that each use is inlined into the pair search.
const auto scalarOverlapMask = [](const Probe& a, std::span<const Ball> balls,
                                  const std::uint32_t* slots) {
  unsigned mask = 0;
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    const Ball& b = balls[slots[lane]];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double reach = a.radius + b.radius;
    mask |= static_cast<unsigned>(!(dx * dx + dy * dy >= reach * reach)) << lane;
  }
  return mask;
};

/// `a` against the grid's balls in the cells within its reach of any ball the grid holds, the
/// grid numbered in `order`.
std::uint64_t meetGridBalls(Probe& a, std::span<Ball> balls, const common::CellLists& cells,
                            common::CellOrder order) {
  // A grid ball overlaps `a` only within a.radius + oversizedRadius of its centre; cellAt clamps
  // like the grid does, so balls outside the box are found in the border cells.
  const double reach = a.radius + cells.oversizedRadius();
  const int columns = cells.columns();
  const auto corner = static_cast<int>(cells.cellAt(a.x - reach, a.y - reach, order));
  const auto opposite = static_cast<int>(cells.cellAt(a.x + reach, a.y + reach, order));
  const int firstColumn = std::min(corner % columns, opposite % columns);
  const int lastColumn = std::max(corner % columns, opposite % columns);
  const int firstRow = std::min(corner / columns, opposite / columns);
  const int lastRow = std::max(corner / columns, opposite / columns);
  std::uint64_t impulses = 0;
  for (int row = firstRow; row <= lastRow; ++row) {
    // One contiguous range of sorted slots per row (read past its end as meet() may).
    impulses +=
        meet(a, balls, cells.slotsIn(row * columns + firstColumn, row * columns + lastColumn + 1),
             scalarOverlapMask);
  }
  return impulses;
}

/// A ball's extent along the sweep: along x, or along −x when the grid is numbered from the
/// upper right, so the sweep runs the way the cells do. NaN sorts first so the order stays
/// strict.
SweepEntry sweepEntry(const Ball& ball, std::uint32_t slot, common::CellOrder order) {
  const double sign = order == common::CellOrder::FromLowerLeft ? 1.0 : -1.0;
  const double centre = sign * ball.x;
  const double left = centre - ball.radius;
  return {std::isnan(left) ? -std::numeric_limits<double>::infinity() : left, centre + ball.radius,
          slot};
}

}  // namespace

LaneTest fastestLaneTest() {
  static const LaneTest fastest = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? LaneTest::Avx2 : LaneTest::Scalar;
  }();
  return fastest;
}

std::uint64_t collideRows(std::span<Ball> balls, const common::CellLists& cells, int firstRow,
                          int endRow, NeighbourSlots& neighbours, LaneTest laneTest) {
  if (laneTest == LaneTest::Avx2) {
    return collideRowsAvx2(balls, cells, firstRow, endRow, neighbours);
  }
  return collideRowsWith(balls, cells, firstRow, endRow, neighbours, scalarOverlapMask);
}

std::uint64_t collideOversized(std::span<Ball> balls, const common::CellLists& cells,
                               common::CellOrder order, std::span<SweepEntry> sweep) {
  const auto slots = cells.oversizedSlots();
  for (std::size_t k = 0; k < slots.size(); ++k)
    sweep[k] = sweepEntry(balls[slots[k]], slots[k], order);
  std::sort(sweep.begin(), sweep.end(), [](const SweepEntry& a, const SweepEntry& b) {
    return std::tie(a.left, a.slot) < std::tie(b.left, b.slot);
  });
  std::uint64_t impulses = 0;
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    Ball& ball = balls[sweep[k].slot];
    Probe a{ball, ball.x, ball.y, ball.radius};
    impulses += meetGridBalls(a, balls, cells, order);
    // Later entries start further on: once one starts beyond this ball's far edge, all do.
    for (std::size_t later = k + 1; later < sweep.size() && sweep[later].left < sweep[k].right;
         ++later) {
      Ball& b = balls[sweep[later].slot];
      const double dx = b.x - a.x;
      const double dy = b.y - a.y;
      const double reach = a.radius + b.radius;
      const double distanceSquared = dx * dx + dy * dy;
      if (!(distanceSquared >= reach * reach))
        impulses += resolveOverlap(a, b, dx, dy, distanceSquared);
    }
    if (a.moved) {
      ball.x = a.x;
      ball.y = a.y;
    }
  }
  return impulses;
}

}  // namespace fooball::elastic
