#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "chart_sample.h"

namespace fooball::gui {

/// The samples of one run in bounded memory, however long the run:
/// - the whole run, decimated: one point per stretch of `stride` samples, holding the
///   stretch's first sample and, per quantity, its lowest and highest value with their times;
///   when `wholeRunCapacity` points are full, neighbouring pairs merge and the stride doubles,
///   so the whole run always fits and no spike is lost;
/// - the recent tail at full resolution: the last `recentCapacity` samples, in a ring buffer.
/// Adding is O(1) amortised and never allocates after construction.
class SampleHistory {
 public:
  /// ~2000 points draw a run at about one point per pixel column; 8192 recent samples hold over
  /// two minutes at 60 samples per second, so the default 20 s window is full resolution.
  static constexpr std::size_t kDefaultWholeRunCapacity = 2000;
  static constexpr std::size_t kDefaultRecentCapacity = 8192;

  /// Both capacities must be at least 2.
  explicit SampleHistory(std::size_t wholeRunCapacity = kDefaultWholeRunCapacity,
                         std::size_t recentCapacity = kDefaultRecentCapacity);

  void clear();
  /// Forgets every sample after `time` (s): the runs were rewound to it, and that future no
  /// longer exists. The recent tail is cut exactly; the whole run is rebuilt from what
  /// copySince() gives before it, so decimated stretches keep their first samples and lose their
  /// extremes (a spike inside one goes: a rewind is rare, a future that never was must not show).
  void dropAfter(double time);

  /// Samples come in non-decreasing time. An earlier time means the run started over without a
  /// clear(), so the history starts over too rather than drawing a line back in time. A sample
  /// whose time is not finite cannot be placed on the time axis and is ignored.
  void add(const ChartSample& sample);

  bool empty() const { return addedCount_ == 0; }
  /// Samples added since the last clear(), stored or not.
  std::uint64_t addedCount() const { return addedCount_; }
  /// The first sample since the last clear(); the history must not be empty.
  const ChartSample& first() const;
  /// The newest sample; the history must not be empty.
  const ChartSample& latest() const;

  /// Every stored sample with time ≥ `since` (s), oldest first, into `out` (cleared first; its
  /// capacity is reused): the first sample of each decimated stretch before the recent tail,
  /// then the tail at full resolution. The first and the latest sample are always stored.
  void copySince(double since, std::vector<ChartSample>& out) const;

  /// What copySince(−∞) returns: at most wholeRunCapacity − 1 + recentCapacity.
  std::size_t storedCount() const;

  /// For drawing `quantity` from `since` (s): calls visit(time, value) in time order, first
  /// with the lowest and highest value of each decimated stretch before the recent tail, then
  /// with every recent sample. A stretch that runs into the tail gives only its extremes from
  /// before the tail, so nothing is visited twice.
  template <typename Visit>
  void forEachValueSince(double since, Quantity quantity, Visit&& visit) const;
  /// The most values forEachValueSince(since, …) visits.
  std::size_t valueCountSince(double since) const;

  /// Samples per stretch of the decimated whole run: 1, 2, 4, …
  std::uint64_t wholeRunStride() const { return stride_; }

 private:
  /// A quantity's value at a time.
  struct TimedValue {
    double time = 0.0;
    double value = 0.0;
  };
  /// One stretch of `stride_` samples of the whole run.
  struct Stretch {
    explicit Stretch(const ChartSample& sample);
    void include(const ChartSample& sample);
    void include(const Stretch& later);

    ChartSample first;
    std::array<TimedValue, kQuantityCount> lowest;
    std::array<TimedValue, kQuantityCount> highest;
  };

  /// The recent sample `age` places before the newest (0 is the newest).
  const ChartSample& recent(std::size_t age) const;
  /// Recent samples with time ≥ `since`: the ages below the returned count.
  std::size_t recentCountSince(double since) const;
  /// Index (in added order) of the oldest sample in the recent tail.
  std::uint64_t firstRecentIndex() const { return addedCount_ - recentSize_; }
  /// Stretches that begin before the recent tail: a prefix of wholeRun_.
  std::size_t olderStretchCount() const;
  /// The first of those stretches whose first sample is at or after `since`.
  std::size_t firstOlderStretchSince(double since) const;

  std::size_t wholeRunCapacity_;
  std::vector<Stretch> wholeRun_;  ///< stretch i begins at sample number i·stride_
  std::uint64_t stride_ = 1;

  std::vector<ChartSample> recentRing_;  ///< sized once to the recent capacity
  std::size_t recentNext_ = 0;           ///< ring slot the next sample goes to
  std::size_t recentSize_ = 0;

  std::uint64_t addedCount_ = 0;
};

template <typename Visit>
void SampleHistory::forEachValueSince(double since, Quantity quantity, Visit&& visit) const {
  const auto index = static_cast<std::size_t>(quantity);
  const std::size_t olderCount = olderStretchCount();
  if (olderCount > 0) {
    const double tailStart = recent(recentSize_ - 1).time;
    for (std::size_t i = firstOlderStretchSince(since); i < olderCount; ++i) {
      const TimedValue& low = wholeRun_[i].lowest[index];
      const TimedValue& high = wholeRun_[i].highest[index];
      const bool lowFirst = low.time <= high.time;
      const TimedValue& earlier = lowFirst ? low : high;
      const TimedValue& later = lowFirst ? high : low;
      if (earlier.time < tailStart) visit(earlier.time, earlier.value);
      // One sample can be both extremes (a flat stretch); it is visited once.
      if (later.time < tailStart && later.time != earlier.time) visit(later.time, later.value);
    }
  }
  for (std::size_t age = recentCountSince(since); age-- > 0;) {
    const ChartSample& sample = recent(age);
    visit(sample.time, sample[quantity]);
  }
}

}  // namespace fooball::gui
