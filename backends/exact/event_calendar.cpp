#include "event_calendar.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fooball::exact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Buckets in a year at the least, so a handful of balls still spread out.
constexpr std::size_t kMinBuckets = 16;

}  // namespace

void EventCalendar::reset(std::size_t ballCount) {
  bucketCount_ = static_cast<std::uint32_t>(std::max(kMinBuckets, kBucketsPerBall * ballCount));
  heads_.assign(bucketCount_ + 2, kEndOfList);
  slots_.resize(ballCount);
  for (std::uint32_t ball = 0; ball < ballCount; ++ball) {
    slots_[ball].time = kInfinity;
    put(ball, kNever);
  }
  front_.reset(ballCount);
  scratch_.reserve(ballCount);
  frontBucket_ = 0;
  yearStart_ = 0.0;
  inverseWidth_ = 0.0;
}

void EventCalendar::set(std::uint32_t ball, double time) {
  Slot& slot = slots_[ball];
  const std::uint32_t place = placeOf(time);
  if (place == slot.place) {
    slot.time = time;
    if (place == kInHeap) front_.update(ball, time);  // a list is unordered: nothing to move
    return;
  }
  remove(ball);
  slot.time = time;
  put(ball, place);
}

EventHeap::Entry EventCalendar::earliest() {
  if (front_.empty()) bringForward();
  if (!front_.empty()) return front_.earliest();
  const std::uint32_t ball = head(kNever);
  return {slots_[ball].time, ball};
}

void EventCalendar::layOut() {
  scratch_.clear();
  for (std::uint32_t ball = 0; ball < slots_.size(); ++ball) {
    if (slots_[ball].place != kNever) scratch_.push_back(ball);
  }
  front_.reset(slots_.size());
  std::fill(heads_.begin(), heads_.begin() + bucketCount_ + 1, kEndOfList);  // the never list stays
  startYear(scratch_);
}

void EventCalendar::shiftOrigin(double offset) {
  yearStart_ -= offset;
  front_.shiftTimes(offset);
  for (std::uint32_t ball = 0; ball < slots_.size(); ++ball) {
    Slot& slot = slots_[ball];
    slot.time -= offset;
    if (slot.place == kNever) continue;
    // Rounding may carry a time that sat on a bucket's edge across it: the rare one moves.
    const std::uint32_t place = placeOf(slot.time);
    if (place == slot.place) continue;
    remove(ball);
    put(ball, place);
  }
}

std::uint32_t EventCalendar::placeOf(double time) const {
  if (!(time < kInfinity)) return kNever;
  // Written so that NaN (−∞ × 0) goes to the heap too.
  const double bucket = (time - yearStart_) * inverseWidth_;
  if (!(bucket >= frontBucket_ + 1.0)) return kInHeap;
  if (bucket >= bucketCount_) return kOverflow;
  return static_cast<std::uint32_t>(bucket);
}

std::uint32_t& EventCalendar::head(std::uint32_t place) {
  if (place == kOverflow) return heads_[bucketCount_];
  if (place == kNever) return heads_[bucketCount_ + 1];
  return heads_[place];
}

void EventCalendar::put(std::uint32_t ball, std::uint32_t place) {
  Slot& slot = slots_[ball];
  slot.place = place;
  if (place == kInHeap) {
    front_.insert(ball, slot.time);
    return;
  }
  linkFirst(slots_, ball, head(place));
}

void EventCalendar::remove(std::uint32_t ball) {
  const Slot& slot = slots_[ball];
  if (slot.place == kInHeap) {
    front_.erase(ball);
    return;
  }
  exact::unlink(slots_, ball, head(slot.place));
}

void EventCalendar::bringForward() {
  while (front_.empty()) {
    std::uint32_t bucket = frontBucket_ + 1;
    while (bucket < bucketCount_ && heads_[bucket] == kEndOfList)
      ++bucket;
    if (bucket < bucketCount_) {
      frontBucket_ = bucket;
      for (std::uint32_t ball = heads_[bucket]; ball != kEndOfList;) {
        const std::uint32_t next = slots_[ball].next;
        put(ball, kInHeap);  // the list is dropped whole below: no unlinking
        ball = next;
      }
      heads_[bucket] = kEndOfList;
      return;
    }
    std::uint32_t& overflow = head(kOverflow);
    if (overflow == kEndOfList) return;  // every time is +∞
    scratch_.clear();
    for (std::uint32_t ball = overflow; ball != kEndOfList; ball = slots_[ball].next)
      scratch_.push_back(ball);
    overflow = kEndOfList;
    startYear(scratch_);
  }
}

void EventCalendar::startYear(std::vector<std::uint32_t>& balls) {
  frontBucket_ = 0;
  yearStart_ = 0.0;
  inverseWidth_ = 0.0;
  if (balls.empty()) return;
  double earliest = kInfinity;
  double sum = 0.0;
  for (const std::uint32_t ball : balls) {
    earliest = std::min(earliest, slots_[ball].time);
    sum += slots_[ball].time;
  }
  const double meanDelay = sum / static_cast<double>(balls.size()) - earliest;
  const double inverseWidth = bucketCount_ / (kYearInMeanDelays * meanDelay);
  // All at one time (or a spread too wide or narrow to divide): one bucket, the heap, holds all.
  if (std::isfinite(inverseWidth) && inverseWidth > 0.0) inverseWidth_ = inverseWidth;
  yearStart_ = earliest;
  for (const std::uint32_t ball : balls)
    put(ball, placeOf(slots_[ball].time));
}

}  // namespace fooball::exact
