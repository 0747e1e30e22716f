#pragma once

#include <cstdint>
#include <vector>

namespace fooball::exact {

/// The event queue: each ball's next event time (s) in an indexed 4-ary min-heap, so changing a
/// ball's time costs O(log N), finding the earliest O(1), and the heap never holds stale
/// copies. A 4-ary heap is half as deep as a binary one and keeps siblings adjacent in memory.
/// No allocation after reset() for a given ball count.
class EventCalendar {
 public:
  /// Gives `ballCount` balls the time +∞.
  void reset(std::size_t ballCount);

  /// Changes the ball's time.
  void set(std::uint32_t ball, double time);

  /// The ball with the earliest time; the calendar must not be empty.
  std::uint32_t earliest() const { return heap_.front().ball; }
  double earliestTime() const { return heap_.front().time; }

  /// Moves the time origin `offset` seconds later. Subtracting the same number keeps the order
  /// (rounding is monotone), so the heap stays valid.
  void shiftOrigin(double offset);

 private:
  struct Entry {
    double time;  ///< s
    std::uint32_t ball;
  };

  void place(std::size_t position, const Entry& entry);
  void siftUp(std::size_t position, const Entry& entry);
  void siftDown(std::size_t position, const Entry& entry);

  std::vector<Entry> heap_;
  std::vector<std::uint32_t> heapPosition_;  ///< per ball, its index in heap_
};

}  // namespace fooball::exact
