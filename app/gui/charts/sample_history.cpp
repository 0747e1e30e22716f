#include "sample_history.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace fooball::gui {
namespace {

/// Whether `candidate` should replace `current` as an extreme: NaN (an undefined value) gives
/// way to any number.
bool isLower(double candidate, double current) {
  return candidate < current || (std::isnan(current) && !std::isnan(candidate));
}
bool isHigher(double candidate, double current) {
  return candidate > current || (std::isnan(current) && !std::isnan(candidate));
}

}  // namespace

SampleHistory::Stretch::Stretch(const ChartSample& sample) : first(sample) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    lowest[q] = highest[q] = {sample.time, sample.values[q]};
  }
}

void SampleHistory::Stretch::include(const ChartSample& sample) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    const double value = sample.values[q];
    if (isLower(value, lowest[q].value)) lowest[q] = {sample.time, value};
    if (isHigher(value, highest[q].value)) highest[q] = {sample.time, value};
  }
}

void SampleHistory::Stretch::include(const Stretch& later) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    if (isLower(later.lowest[q].value, lowest[q].value)) lowest[q] = later.lowest[q];
    if (isHigher(later.highest[q].value, highest[q].value)) highest[q] = later.highest[q];
  }
}

SampleHistory::SampleHistory(std::size_t wholeRunCapacity, std::size_t recentCapacity)
    : wholeRunCapacity_(std::max<std::size_t>(wholeRunCapacity, 2)),
      recentRing_(std::max<std::size_t>(recentCapacity, 2)) {
  wholeRun_.reserve(wholeRunCapacity_);
}

void SampleHistory::clear() {
  wholeRun_.clear();
  stride_ = 1;
  recentNext_ = 0;
  recentSize_ = 0;
  addedCount_ = 0;
}

void SampleHistory::dropAfter(double time) {
  if (empty() || latest().time <= time) return;
  std::vector<ChartSample> kept;
  copySince(-std::numeric_limits<double>::infinity(), kept);
  std::erase_if(kept, [time](const ChartSample& sample) { return sample.time > time; });
  clear();
  for (const ChartSample& sample : kept)
    add(sample);
}

void SampleHistory::add(const ChartSample& sample) {
  if (!std::isfinite(sample.time)) return;
  if (!empty() && sample.time < latest().time) clear();

  if (addedCount_ % stride_ != 0) {
    wholeRun_.back().include(sample);
  } else {
    wholeRun_.emplace_back(sample);
    if (wholeRun_.size() == wholeRunCapacity_) {
      // Stretches 2k and 2k+1 become stretch k, which begins at a multiple of the new stride.
      std::size_t merged = 0;
      for (std::size_t i = 0; i < wholeRun_.size(); i += 2) {
        Stretch stretch = wholeRun_[i];
        if (i + 1 < wholeRun_.size()) stretch.include(wholeRun_[i + 1]);
        wholeRun_[merged++] = stretch;
      }
      wholeRun_.erase(wholeRun_.begin() + static_cast<std::ptrdiff_t>(merged), wholeRun_.end());
      stride_ *= 2;
    }
  }

  recentRing_[recentNext_] = sample;
  recentNext_ = (recentNext_ + 1) % recentRing_.size();
  recentSize_ = std::min(recentSize_ + 1, recentRing_.size());
  ++addedCount_;
}

const ChartSample& SampleHistory::first() const {
  assert(!empty());
  return wholeRun_.front().first;  // sample number 0 begins the first stretch at any stride
}

const ChartSample& SampleHistory::latest() const {
  assert(!empty());
  return recent(0);
}

const ChartSample& SampleHistory::recent(std::size_t age) const {
  const std::size_t capacity = recentRing_.size();
  return recentRing_[(recentNext_ + capacity - 1 - age) % capacity];
}

std::size_t SampleHistory::recentCountSince(double since) const {
  // Recent times fall with age: binary search for the first age before `since`.
  std::size_t count = 0;
  std::size_t searchCount = recentSize_;
  while (searchCount > 0) {
    const std::size_t half = searchCount / 2;
    const std::size_t age = count + half;
    if (recent(age).time >= since) {
      count = age + 1;
      searchCount -= half + 1;
    } else {
      searchCount = half;
    }
  }
  return count;
}

std::size_t SampleHistory::olderStretchCount() const {
  // Stretch i begins at sample number i·stride_; count those that begin before the tail.
  const std::uint64_t before = (firstRecentIndex() + stride_ - 1) / stride_;
  return static_cast<std::size_t>(std::min<std::uint64_t>(before, wholeRun_.size()));
}

std::size_t SampleHistory::firstOlderStretchSince(double since) const {
  const auto older = wholeRun_.begin() + static_cast<std::ptrdiff_t>(olderStretchCount());
  const auto found =
      std::partition_point(wholeRun_.begin(), older,
                           [since](const Stretch& stretch) { return stretch.first.time < since; });
  return static_cast<std::size_t>(found - wholeRun_.begin());
}

std::size_t SampleHistory::storedCount() const {
  return olderStretchCount() + recentSize_;
}

std::size_t SampleHistory::valueCountSince(double since) const {
  return 2 * (olderStretchCount() - firstOlderStretchSince(since)) + recentCountSince(since);
}

void SampleHistory::copySince(double since, std::vector<ChartSample>& out) const {
  out.clear();
  for (std::size_t i = firstOlderStretchSince(since); i < olderStretchCount(); ++i) {
    out.push_back(wholeRun_[i].first);
  }
  for (std::size_t age = recentCountSince(since); age-- > 0;)
    out.push_back(recent(age));
}

}  // namespace fooball::gui
