#include "neighbour_slots.h"

#include <algorithm>
#include <cstring>

namespace fooball::elastic {

void NeighbourSlots::gather(std::span<const std::uint32_t> hereAndRight,
                            std::span<const std::uint32_t> above) {
  constexpr std::size_t kCopy = common::CellLists::kReadPastEnd;
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

}  // namespace fooball::elastic
