#include "pair_collisions.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

namespace fooball::elastic {

namespace {

/// The lower ball of the pairs being resolved: its centre and radius stay in registers while
/// it meets its candidates, and go back to memory only if a collision moved it.
struct Probe {
  Ball& ball;
  double x, y;    ///< m
  double radius;  ///< m
  bool moved = false;
};

/// Separates and collides `a` with `b`, which overlap: their centres are (dx, dy) apart (m),
/// the squared distance `distanceSquared` below the squared sum of their radii. Out of line:
/// most candidates do not overlap, and the test loop stays small.
[[gnu::noinline]] bool resolveOverlap(Probe& a, Ball& b, double dx, double dy,
                                      double distanceSquared) {
  Ball& ballA = a.ball;
  const double reach = a.radius + b.radius;
  double distance = std::sqrt(distanceSquared);
  const double penetration = reach - distance;
  if (distance == 0.0) {
    // Coincident centres: push apart along the relative velocity if there is one, else along x.
    dx = ballA.vx - b.vx;
    dy = ballA.vy - b.vy;
    distance = std::hypot(dx, dy);
    if (distance == 0.0) {
      dx = 1.0;
      dy = 0.0;
      distance = 1.0;
    }
  }
  const double nx = dx / distance;
  const double ny = dy / distance;
  // Shares of the correction: b moves ma/(ma+mb) of it, a the rest; written as 1/(1 + m/m')
  // so mass ratios of 1e8 neither overflow nor lose the light ball's share.
  const double shareA = 1.0 / (1.0 + ballA.mass / b.mass);
  const double shareB = 1.0 / (1.0 + b.mass / ballA.mass);
  a.x -= nx * penetration * shareA;
  a.y -= ny * penetration * shareA;
  a.moved = true;
  b.x += nx * penetration * shareB;
  b.y += ny * penetration * shareB;

  const double closingSpeed =
      (ballA.vx - b.vx) * nx + (ballA.vy - b.vy) * ny;  // m/s, > 0 approaching
  if (closingSpeed <= 0.0) return false;
  // Δv_a = −2 mb/(ma+mb)·u_n, Δv_b = +2 ma/(ma+mb)·u_n: momentum and energy conserved exactly.
  const double kickA = 2.0 * shareA * closingSpeed;
  const double kickB = 2.0 * shareB * closingSpeed;
  ballA.vx -= nx * kickA;
  ballA.vy -= ny * kickA;
  b.vx += nx * kickB;
  b.vy += ny * kickB;
  return true;
}

constexpr std::size_t kLanes = NeighbourSlots::kLanes;

/// How many cells ahead the pair search prefetches the row above.
constexpr int kPrefetchCells = 4;

/// Bit j set when `a` overlaps the ball in slot slots[j], j < kLanes. Written as
/// !(d² ≥ reach²) so a NaN counts as an overlap, as in the one-by-one test.
inline unsigned overlapMask(const Probe& a, std::span<const Ball> balls,
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
}

/// Lanes 0 … count−1.
inline unsigned lanesBelow(std::size_t count) {
  return (1u << std::min(count, kLanes)) - 1;
}

/// `a` against the balls in the slots `candidates`; returns the impulses exchanged. Inlined
/// into each caller: called once per ball of the pair search, a call costs ~10% there.
[[gnu::always_inline]] inline std::uint64_t meet(Probe& a, std::span<Ball> balls,
                                                 std::span<const std::uint32_t> candidates) {
  std::uint64_t impulses = 0;
  for (std::size_t base = 0; base < candidates.size(); base += kLanes) {
    const std::uint32_t* slots = candidates.data() + base;
    const unsigned lanes = lanesBelow(candidates.size() - base);
    unsigned overlapping = overlapMask(a, balls, slots) & lanes;
    while (overlapping != 0) {
      const int lane = std::countr_zero(overlapping);
      Ball& b = balls[slots[lane]];
      const double dx = b.x - a.x;
      const double dy = b.y - a.y;
      impulses += resolveOverlap(a, b, dx, dy, dx * dx + dy * dy);
      // `a` has moved: the later lanes are tested again from its new centre, exactly as one by
      // one.
      overlapping = overlapMask(a, balls, slots) & lanes & ~((2u << lane) - 1);
    }
  }
  return impulses;
}

/// `a` against the grid's balls in the cells within its reach of any ball the grid holds.
std::uint64_t meetGridBalls(Probe& a, std::span<Ball> balls, const CellLists& cells) {
  // A grid ball overlaps `a` only within a.radius + oversizedRadius of its centre; cellAt clamps
  // like the grid does, so balls outside the box are found in the border cells.
  const double reach = a.radius + cells.oversizedRadius();
  const int columns = cells.columns();
  const auto low = static_cast<int>(cells.cellAt(a.x - reach, a.y - reach));
  const auto high = static_cast<int>(cells.cellAt(a.x + reach, a.y + reach));
  std::uint64_t impulses = 0;
  for (int row = low / columns; row <= high / columns; ++row) {
    // One contiguous range of sorted slots per row (read past its end as meet() may).
    impulses += meet(
        a, balls, cells.slotsIn(row * columns + low % columns, row * columns + high % columns + 1));
  }
  return impulses;
}

/// Where a ball's sweep entry sorts: its left edge, with NaN first so the order stays strict.
double leftEdge(const Ball& ball) {
  const double left = ball.x - ball.radius;
  return std::isnan(left) ? -std::numeric_limits<double>::infinity() : left;
}

}  // namespace

void NeighbourSlots::gather(std::span<const std::uint32_t> hereAndRight,
                            std::span<const std::uint32_t> above) {
  constexpr std::size_t kCopy = CellLists::kReadPastEnd;
  size_ = hereAndRight.size() + above.size();
  std::uint32_t* slots = usual_.data();
  if (hereAndRight.size() <= kCopy && above.size() <= kCopy) {
    // Fixed-size copies, no loop to mispredict; what they read past a range is overwritten or
    // beyond size_.
    std::memcpy(slots, hereAndRight.data(), kCopy * sizeof(std::uint32_t));
    std::memcpy(slots + hereAndRight.size(), above.data(), kCopy * sizeof(std::uint32_t));
  } else {
    if (crowded_.size() < size_ + kLanes) crowded_.resize(size_ + kLanes);
    slots = crowded_.data();
    std::copy(hereAndRight.begin(), hereAndRight.end(), slots);
    std::copy(above.begin(), above.end(), slots + hereAndRight.size());
  }
  // The lanes past the end read the cell's first ball and are masked out. That ball, not any
  // other: it is the worker's own, so the reads race with no other worker's writes.
  std::fill_n(slots + size_, kLanes, slots[0]);
  slots_ = slots;
}

std::uint64_t collideRows(std::span<Ball> balls, const CellLists& cells, int firstRow, int endRow,
                          NeighbourSlots& neighbours) {
  // No balls, no pairs; and the prefetches below may not index an empty span.
  if (balls.empty()) return 0;
  const int columns = cells.columns();
  std::uint64_t impulses = 0;
  for (int row = firstRow; row < endRow; ++row) {
    const bool rowAbove = row + 1 < cells.rows();
    for (int column = 0; column < columns; ++column) {
      const int cell = row * columns + column;
      // The balls of the row above are met here for the first time this substep: fetch those a
      // few cells ahead now, so their cache misses overlap with this cell's work.
      if (rowAbove && column + kPrefetchCells < columns) {
        // The first two slots, however many the cell has (the slots may be read past a range):
        // a loop of one or two turns would cost a mispredicted branch per cell.
        const std::uint32_t* ahead = cells.slotsFrom(cell + columns + kPrefetchCells);
        __builtin_prefetch(&balls[ahead[0]]);
        __builtin_prefetch(&balls[ahead[1]]);
      }
      const std::size_t hereCount = cells.slotsIn(cell, cell + 1).size();
      if (hereCount == 0) continue;
      const int aboveLeft = cell + columns - (column > 0 ? 1 : 0);
      const int aboveEnd = cell + columns + (column + 1 < columns ? 2 : 1);
      neighbours.gather(cells.slotsIn(cell, std::min(cell + 2, (row + 1) * columns)),
                        rowAbove ? cells.slotsIn(aboveLeft, aboveEnd) : cells.slotsIn(cell, cell));
      for (std::size_t k = 0; k < hereCount; ++k) {
        Ball& ball = balls[neighbours[k]];
        Probe a{ball, ball.x, ball.y, ball.radius};
        impulses += meet(a, balls, neighbours.after(k));
        if (a.moved) {
          ball.x = a.x;
          ball.y = a.y;
        }
      }
    }
  }
  return impulses;
}

std::uint64_t collideOversized(std::span<Ball> balls, const CellLists& cells,
                               std::span<SweepEntry> sweep) {
  const auto slots = cells.oversizedSlots();
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const Ball& ball = balls[slots[k]];
    sweep[k] = {leftEdge(ball), ball.x + ball.radius, slots[k]};
  }
  std::sort(sweep.begin(), sweep.end(), [](const SweepEntry& a, const SweepEntry& b) {
    return std::tie(a.left, a.slot) < std::tie(b.left, b.slot);
  });
  std::uint64_t impulses = 0;
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    Ball& ball = balls[sweep[k].slot];
    Probe a{ball, ball.x, ball.y, ball.radius};
    impulses += meetGridBalls(a, balls, cells);
    // Later entries start further right: once one starts beyond this ball's right edge, all do.
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
