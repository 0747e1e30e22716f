#pragma once

#include <cstdint>
#include <vector>

#include "event_heap.h"
#include "linked_lists.h"

namespace fooball::exact {

/// The event queue: each ball's next event time (s), earliest first. A calendar queue (Brown
/// 1988; with a heap for the front bucket as in Paul 2007 and Smallenburg 2022): the near future
/// is cut into buckets of equal width, each an unsorted list, and only the front bucket is kept
/// in order, in a small heap. A ball's new time goes into its bucket in O(1) and leaves it in
/// O(1), so an event costs O(1) whatever the ball count, where a heap of every ball costs
/// O(log N) cache-missing levels (at 10⁴ balls the heap's sifts were 40% of the event loop).
///
/// A "year" of kBucketsPerBall buckets per ball spans kYearInMeanDelays times the balls' mean
/// time to their next event, so the front buckets hold about two balls each. Times beyond the
/// year wait in an overflow list, and the next year is laid out from them when this one is used
/// up; +∞ (and NaN) are kept apart and never laid out. The bucket of a time is
/// floor((time − yearStart)·inverseWidth), monotone in the time, so every ball in the front heap
/// is no later than any ball in a bucket behind it: earliest() is the exact minimum, ties broken
/// by the heap's fixed rules (deterministic). No allocation after reset() for a given ball count.
class EventCalendar {
 public:
  /// Gives `ballCount` balls the time +∞.
  void reset(std::size_t ballCount);

  /// Changes the ball's time.
  void set(std::uint32_t ball, double time);

  /// The ball with the earliest time and that time (+∞ when every time is); there must be a ball.
  /// Not const: it may bring the next bucket forward.
  EventHeap::Entry earliest();

  /// Lays the year out afresh from the balls' times: call after setting many of them at once,
  /// so the bucket width follows their spread.
  void layOut();

  /// Moves the time origin `offset` seconds later: every time becomes time − offset, rounded
  /// exactly as the caller rounds its own copies.
  void shiftOrigin(double offset);

 private:
  /// Buckets per ball: about two balls per front bucket, with the year below.
  static constexpr std::size_t kBucketsPerBall = 2;
  /// The year, in mean delays to the balls' next events: an exponential spread leaves e⁻⁴ ≈ 2%
  /// of the balls beyond it.
  static constexpr double kYearInMeanDelays = 4.0;

  /// Where a ball waits: a bucket of the year (0 … bucketCount−1), or one of these.
  static constexpr std::uint32_t kInHeap = 0xfffffffdu;
  static constexpr std::uint32_t kOverflow = 0xfffffffeu;  ///< beyond the year
  static constexpr std::uint32_t kNever = 0xffffffffu;     ///< +∞ or NaN

  struct Slot {
    double time;  ///< s
    std::uint32_t place;
    std::uint32_t next;      ///< in its list, or kEndOfList
    std::uint32_t previous;  ///< in its list, or kEndOfList
  };

  std::uint32_t placeOf(double time) const;
  /// Where the list of `place` (a bucket, kOverflow or kNever) begins.
  std::uint32_t& head(std::uint32_t place);
  void put(std::uint32_t ball, std::uint32_t place);
  void remove(std::uint32_t ball);
  /// Moves buckets into the heap until it holds a ball, laying out the next year if need be;
  /// leaves it empty only when every time is +∞.
  void bringForward();
  /// Starts a year at the earliest of the balls in `balls` (a list of kOverflow balls, or all
  /// balls) and puts them in their places.
  void startYear(std::vector<std::uint32_t>& balls);

  std::vector<Slot> slots_;           ///< per ball
  EventHeap front_;                   ///< the balls of buckets 0 … frontBucket_
  std::vector<std::uint32_t> heads_;  ///< per bucket, then the overflow and never lists
  std::uint32_t bucketCount_ = 0;
  std::uint32_t frontBucket_ = 0;       ///< the last bucket moved into the heap
  double yearStart_ = 0.0;              ///< s, where bucket 0 begins
  double inverseWidth_ = 0.0;           ///< 1/s; 0 puts every finite time into the heap
  std::vector<std::uint32_t> scratch_;  ///< the balls startYear lays out
};

}  // namespace fooball::exact
