#include "exact/event_calendar.h"

#include <limits>

namespace fooball::exact {

namespace {

constexpr std::size_t kArity = 4;

}  // namespace

void EventCalendar::reset(std::size_t ballCount) {
  heap_.resize(ballCount);
  heapPosition_.resize(ballCount);
  for (std::size_t ball = 0; ball < ballCount; ++ball) {
    heap_[ball] = {std::numeric_limits<double>::infinity(), static_cast<std::uint32_t>(ball)};
    heapPosition_[ball] = static_cast<std::uint32_t>(ball);
  }
}

void EventCalendar::set(std::uint32_t ball, double time) {
  const std::size_t position = heapPosition_[ball];
  const double previous = heap_[position].time;
  if (time < previous) {
    siftUp(position, {time, ball});
  } else if (time > previous) {
    siftDown(position, {time, ball});
  }
}

void EventCalendar::shiftOrigin(double offset) {
  for (Entry& entry : heap_)
    entry.time -= offset;
}

void EventCalendar::place(std::size_t position, const Entry& entry) {
  heap_[position] = entry;
  heapPosition_[entry.ball] = static_cast<std::uint32_t>(position);
}

void EventCalendar::siftUp(std::size_t position, const Entry& entry) {
  while (position > 0) {
    const std::size_t parent = (position - 1) / kArity;
    if (!(entry.time < heap_[parent].time)) break;
    place(position, heap_[parent]);
    position = parent;
  }
  place(position, entry);
}

void EventCalendar::siftDown(std::size_t position, const Entry& entry) {
  const std::size_t size = heap_.size();
  while (true) {
    const std::size_t first = kArity * position + 1;
    if (first >= size) break;
    std::size_t earliest = first;
    if (first + kArity <= size) {  // a full family: a tournament of selects, no branches
      const std::size_t left = heap_[first + 1].time < heap_[first].time ? first + 1 : first;
      const std::size_t right =
          heap_[first + 3].time < heap_[first + 2].time ? first + 3 : first + 2;
      earliest = heap_[right].time < heap_[left].time ? right : left;
    } else {
      for (std::size_t child = first + 1; child < size; ++child) {
        if (heap_[child].time < heap_[earliest].time) earliest = child;
      }
    }
    if (!(heap_[earliest].time < entry.time)) break;
    place(position, heap_[earliest]);
    position = earliest;
  }
  place(position, entry);
}

}  // namespace fooball::exact
