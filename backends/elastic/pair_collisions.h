#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "balls.h"
#include "cell_lists.h"

namespace fooball::elastic {

/// The slots a cell's balls meet: its own and the right neighbour's (one contiguous range of the
/// sorted slots), then the three cells above (another), gathered into one array so each ball
/// runs one candidate loop, not two. One per worker, reused for every cell: it grows only for a
/// crowded cell.
class NeighbourSlots {
 public:
  /// `hereAndRight` starts with the cell's own balls, at least one. Both ranges lie in CellLists'
  /// sorted slots, even when empty, so CellLists::kReadPastEnd entries may be read after them.
  void gather(std::span<const std::uint32_t> hereAndRight, std::span<const std::uint32_t> above);

  std::uint32_t operator[](std::size_t k) const { return slots_[k]; }
  /// The slots after the k-th: what the k-th ball of the cell meets. kLanes entries may be read
  /// past its end (the cell's first ball's slot).
  std::span<const std::uint32_t> after(std::size_t k) const {
    return {slots_ + k + 1, size_ - k - 1};
  }

  std::size_t memoryBytes() const {
    return sizeof(*this) + crowded_.capacity() * sizeof(std::uint32_t);
  }

  /// Candidates are tested this many at a time, without branches: a loop over a handful of
  /// candidates ends at an unpredictable count, and each mispredicted end costs as much as a
  /// dozen tests. With eight lanes most balls need one round.
  static constexpr std::size_t kLanes = 8;

 private:
  /// Room for the usual neighbourhood: two fixed-size copies and the lanes past their end.
  /// Inside the object, so a worker's scratch lies on its own cache lines (WorkerState).
  std::array<std::uint32_t, 2 * CellLists::kReadPastEnd + kLanes> usual_{};
  std::vector<std::uint32_t> crowded_;          ///< for a neighbourhood too big for usual_: rare
  const std::uint32_t* slots_ = usual_.data();  ///< usual_ or crowded_, set by gather
  std::size_t size_ = 0;
};

/// Resolves every overlapping pair with its lower ball in rows [firstRow, endRow) of `cells`
/// (built on the balls' current centres), cell by cell in row-major order, each ball against
/// the later balls of its cell, the cell to its right and the three cells above (Gauss–Seidel,
/// deterministic). Touches the balls of rows firstRow … endRow only, so row bands two apart can
/// run at the same time. For each overlapping pair:
/// - separates it along the line of centres, each ball moved in inverse proportion to its mass
///   so the centre of mass stays put, exactly to contact (no over-push);
/// - exchanges the elastic impulse J = 2μ·u_n (μ the reduced mass, u_n the closing speed) only
///   when the pair is approaching, so a pair that is already separating is not collided again;
/// - coincident centres get a deterministic normal instead of a division by zero.
/// How collideRows tests a ball against its (up to) eight candidates at a time. Both give the
/// same results bit for bit: the same IEEE operations in the same order per lane, and no fused
/// multiply-add (AVX2 does not include FMA).
enum class LaneTest {
  Scalar,  ///< one lane after another, on any x86-64
  Avx2,    ///< four lanes per instruction (pair_collisions_avx2.cpp)
};

/// The fastest lane test this CPU runs: Avx2 where it has AVX2.
LaneTest fastestLaneTest();

/// `neighbours` is the calling worker's scratch; `laneTest` must run on this CPU. Returns the
/// number of impulses exchanged.
std::uint64_t collideRows(std::span<Ball> balls, const CellLists& cells, int firstRow, int endRow,
                          NeighbourSlots& neighbours, LaneTest laneTest = fastestLaneTest());

/// collideRows with LaneTest::Avx2, compiled for AVX2: call it only on a CPU that has it.
std::uint64_t collideRowsAvx2(std::span<Ball> balls, const CellLists& cells, int firstRow,
                              int endRow, NeighbourSlots& neighbours);

/// An oversized ball's extent along x (m) when collideOversized begins, for its sweep.
struct SweepEntry {
  double left;
  double right;
  std::uint32_t slot;
};

/// Resolves every overlapping pair with an oversized ball of `cells` (built on the balls'
/// current centres), as collideRows does: the oversized balls in order of their left edges,
/// each against the grid's balls in the cells its reach covers, then against the later
/// oversized balls that it meets along x (a sweep, so a few hundred big balls cost no
/// quadratic pass). Touches any ball: run it while no other worker touches balls.
/// `sweep` is scratch with one entry per oversized ball. Returns the impulses exchanged.
std::uint64_t collideOversized(std::span<Ball> balls, const CellLists& cells,
                               std::span<SweepEntry> sweep);

}  // namespace fooball::elastic
