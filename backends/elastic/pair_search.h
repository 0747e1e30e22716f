// The pair search of collideRows (pair_collisions.h), written once for any lane test: each
// translation unit that includes this gets its own copy (internal linkage), so
// pair_collisions_avx2.cpp can compile it for AVX2 while pair_collisions.cpp keeps the baseline
// instruction set. Include it only from those two files.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "balls.h"
#include "common/cell_lists.h"
#include "neighbour_slots.h"

namespace fooball::elastic {
namespace {  // one copy per instruction set, see above

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

/// Lanes 0 … count−1.
inline unsigned lanesBelow(std::size_t count) {
  return (1u << std::min(count, kLanes)) - 1;
}

/// `a` against the balls in the slots `candidates`; returns the impulses exchanged.
/// `overlapMask(a, balls, slots)` sets bit j when `a` overlaps the ball in slots[j], j < kLanes.
/// Inlined into each caller: called once per ball of the pair search, a call costs ~10% there.
template <class OverlapMask>
[[gnu::always_inline]] inline std::uint64_t meet(Probe& a, std::span<Ball> balls,
                                                 std::span<const std::uint32_t> candidates,
                                                 OverlapMask overlapMask) {
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

/// collideRows (pair_collisions.h) with the given lane test.
template <class OverlapMask>
[[gnu::always_inline]] inline std::uint64_t collideRowsWith(std::span<Ball> balls,
                                                            const common::CellLists& cells,
                                                            int firstRow, int endRow,
                                                            NeighbourSlots& neighbours,
                                                            OverlapMask overlapMask) {
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
        impulses += meet(a, balls, neighbours.after(k), overlapMask);
        if (a.moved) {
          ball.x = a.x;
          ball.y = a.y;
        }
      }
    }
  }
  return impulses;
}

}  // namespace
}  // namespace fooball::elastic
