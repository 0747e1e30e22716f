#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/cell_lists.h"

namespace fooball::elastic {

/// The slots a cell's balls meet: its own and the right neighbour's (one contiguous range of the
/// sorted slots), then the three cells above (another), gathered into one array so each ball
/// runs one candidate loop, not two. One per worker, reused for every cell: it grows only for a
/// crowded cell.
class NeighbourSlots {
 public:
  NeighbourSlots() { crowded_.reserve(kCrowdedRoom); }

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
  std::array<std::uint32_t, 2 * common::CellLists::kReadPastEnd + kLanes> usual_{};
  /// Slots crowded_ holds from the start (256 bytes a worker, under 0.3 bytes a ball at 1'000
  /// balls), so that a step allocates only for a neighbourhood of more than 56 balls, which
  /// takes balls piled deep into each other: which cells crowd most depends on the trajectory,
  /// and a first crowd may come at any step (big balls among 3'000 small ones crowd up to 23).
  static constexpr std::size_t kCrowdedRoom = 64;
  std::vector<std::uint32_t> crowded_;          ///< for a neighbourhood too big for usual_: rare
  const std::uint32_t* slots_ = usual_.data();  ///< usual_ or crowded_, set by gather
  std::size_t size_ = 0;
};

}  // namespace fooball::elastic
