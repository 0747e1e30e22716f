#include "event_heap.h"

namespace fooball::exact {

namespace {

constexpr std::size_t kArity = 4;
constexpr std::size_t kCacheLine = 64;  // bytes

}  // namespace

void EventHeap::reset(std::size_t ballCount) {
  constexpr std::size_t kEntriesPerLine = kCacheLine / sizeof(Entry);
  storage_.resize(ballCount + kEntriesPerLine - 1);
  // Entry 1 (the first child of the root, and with it every family) starts a cache line.
  const auto lineOffset = reinterpret_cast<std::uintptr_t>(storage_.data() + 1) % kCacheLine;
  skew_ = (kEntriesPerLine - lineOffset / sizeof(Entry)) % kEntriesPerLine;
  size_ = 0;
  heapPosition_.resize(ballCount);
}

void EventHeap::insert(std::uint32_t ball, double time) {
  siftUp(size_++, {time, ball});
}

void EventHeap::erase(std::uint32_t ball) {
  const std::size_t position = heapPosition_[ball];
  const Entry last = heap()[--size_];
  if (position == size_) return;
  replace(position, last, heap()[position].time);
}

void EventHeap::update(std::uint32_t ball, double time) {
  const std::size_t position = heapPosition_[ball];
  replace(position, {time, ball}, heap()[position].time);
}

void EventHeap::replace(std::size_t position, const Entry& entry, double previous) {
  if (entry.time < previous) {
    siftUp(position, entry);
  } else if (entry.time > previous) {
    siftDown(position, entry);
  } else {
    place(position, entry);
  }
}

void EventHeap::shiftTimes(double offset) {
  Entry* entries = heap();
  for (std::size_t position = 0; position < size_; ++position)
    entries[position].time -= offset;
}

void EventHeap::place(std::size_t position, const Entry& entry) {
  heap()[position] = entry;
  heapPosition_[entry.ball] = static_cast<std::uint32_t>(position);
}

void EventHeap::siftUp(std::size_t position, const Entry& entry) {
  const Entry* entries = heap();
  while (position > 0) {
    const std::size_t parent = (position - 1) / kArity;
    if (!(entry.time < entries[parent].time)) break;
    place(position, entries[parent]);
    position = parent;
  }
  place(position, entry);
}

/// Floyd's variant: the hole at `position` first sinks to the bottom along the earliest children,
/// without comparing against the entry, then the entry rises from there. A later time usually
/// belongs near the bottom (most entries are there), so this saves the per-level comparison with
/// the entry and its unpredictable branch. The entry cannot rise above `position`: everything
/// above it is no later than the old entry there, hence than this one.
void EventHeap::siftDown(std::size_t position, const Entry& entry) {
  const Entry* entries = heap();
  while (true) {
    const std::size_t first = kArity * position + 1;
    std::size_t earliest = first;
    if (first + kArity <= size_) {  // a full family: a tournament decided by arithmetic, no jumps
      const Entry* child = entries + first;
      const auto left = static_cast<std::size_t>(child[1].time < child[0].time);
      const std::size_t right = 2 + static_cast<std::size_t>(child[3].time < child[2].time);
      const auto rightWins = static_cast<std::size_t>(child[right].time < child[left].time);
      earliest = first + left + (right - left) * rightWins;
    } else if (first < size_) {
      for (std::size_t other = first + 1; other < size_; ++other) {
        if (entries[other].time < entries[earliest].time) earliest = other;
      }
    } else {
      break;
    }
    place(position, entries[earliest]);
    position = earliest;
  }
  siftUp(position, entry);
}

}  // namespace fooball::exact
