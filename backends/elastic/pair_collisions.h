#pragma once

#include <cstdint>
#include <span>

#include "balls.h"
#include "common/cell_lists.h"
#include "neighbour_slots.h"

namespace fooball::elastic {

/// How collideRows tests a ball against its (up to) eight candidates at a time. Both give the
/// same results bit for bit: the same IEEE operations in the same order per lane, and no fused
/// multiply-add (AVX2 does not include FMA).
enum class LaneTest {
  Scalar,  ///< one lane after another, on any x86-64
  Avx2,    ///< four lanes per instruction (pair_collisions_avx2.cpp)
};

/// The fastest lane test this CPU runs: Avx2 where it has AVX2.
LaneTest fastestLaneTest();

/// Resolves every overlapping pair with its lower ball in rows [firstRow, endRow) of `cells`
/// (built on the balls' current centres; rows, columns, "right" and "above" count from the
/// corner their CellOrder starts at), cell by cell in row-major order, each ball against the
/// later balls of its cell, the cell to its right and the three cells above (Gauss–Seidel,
/// deterministic). Touches the balls of rows firstRow … endRow only, so row bands two apart can
/// run at the same time. For each overlapping pair:
/// - separates it along the line of centres, each ball moved in inverse proportion to its mass
///   so the centre of mass stays put, exactly to contact (no over-push);
/// - exchanges the elastic impulse J = 2μ·u_n (μ the reduced mass, u_n the closing speed) only
///   when the pair is approaching, so a pair that is already separating is not collided again;
/// - coincident centres get a deterministic normal instead of a division by zero.
/// `neighbours` is the calling worker's scratch; `laneTest` must run on this CPU. Returns the
/// number of impulses exchanged.
std::uint64_t collideRows(std::span<Ball> balls, const common::CellLists& cells, int firstRow,
                          int endRow, NeighbourSlots& neighbours,
                          LaneTest laneTest = fastestLaneTest());

/// collideRows with LaneTest::Avx2, compiled for AVX2: call it only on a CPU that has it.
std::uint64_t collideRowsAvx2(std::span<Ball> balls, const common::CellLists& cells, int firstRow,
                              int endRow, NeighbourSlots& neighbours);

/// An oversized ball's extent (m) along the sweep's axis when collideOversized begins.
struct SweepEntry {
  double left;
  double right;
  std::uint32_t slot;
};

/// Resolves every overlapping pair with an oversized ball of `cells` (built on the balls'
/// current centres, numbered in `order`), as collideRows does: the oversized balls in order
/// along x (from the left, or from the right when `order` starts at the upper right), each
/// against the grid's balls in the cells its reach covers, then against the later oversized
/// balls that it meets along x (a sweep, so a few hundred big balls cost no quadratic pass).
/// Touches any ball: run it while no other worker touches balls. `sweep` is scratch with one
/// entry per oversized ball. Returns the impulses exchanged.
std::uint64_t collideOversized(std::span<Ball> balls, const common::CellLists& cells,
                               common::CellOrder order, std::span<SweepEntry> sweep);

}  // namespace fooball::elastic
