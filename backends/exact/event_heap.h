#pragma once

#include <cstdint>
#include <vector>

namespace fooball::exact {

/// An indexed 4-ary min-heap of balls keyed by time (s): inserting, removing or changing a
/// ball's time costs O(log n), finding the earliest O(1), and each ball is in it at most once.
/// A 4-ary heap is half as deep as a binary one, and its storage is offset so that each family
/// of 4 siblings (16-byte entries) fills exactly one 64-byte cache line: a sift touches one line
/// per level. No allocation after reset() for a given ball count.
class EventHeap {
 public:
  struct alignas(16) Entry {
    double time;  ///< s
    std::uint32_t ball;
  };

  /// Empties the heap and makes room for balls 0 … ballCount−1.
  void reset(std::size_t ballCount);

  bool empty() const { return size_ == 0; }
  /// The ball with the earliest time; the heap must not be empty.
  const Entry& earliest() const { return heap()[0]; }

  /// Adds a ball that is not in the heap.
  void insert(std::uint32_t ball, double time);
  /// Removes a ball that is in the heap.
  void erase(std::uint32_t ball);
  /// Changes the time of a ball that is in the heap.
  void update(std::uint32_t ball, double time);
  /// Subtracts `offset` from every time: rounding is monotone, so the order stays valid.
  void shiftTimes(double offset);

 private:
  /// The heap proper: entry k sits at storage_[k + skew_], with skew_ chosen so that the
  /// children 4p+1 … 4p+4 of every entry p start on a cache line.
  Entry* heap() { return storage_.data() + skew_; }
  const Entry* heap() const { return storage_.data() + skew_; }

  void place(std::size_t position, const Entry& entry);
  void siftUp(std::size_t position, const Entry& entry);
  void siftDown(std::size_t position, const Entry& entry);
  /// Puts `entry` at `position`, whose old entry had time `previous`, and restores the order.
  void replace(std::size_t position, const Entry& entry, double previous);

  std::vector<Entry> storage_;  ///< the heap after up to 3 entries of alignment slack
  std::size_t skew_ = 0;
  std::size_t size_ = 0;
  std::vector<std::uint32_t> heapPosition_;  ///< per ball, its index in the heap if it is in it
};

}  // namespace fooball::exact
