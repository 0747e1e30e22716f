#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace fooball::exact {

/// Doubly linked lists threaded through per-ball records (anything with `next` and `previous`
/// ball indices), each list known by its first ball: adding or removing a ball is O(1) and
/// allocates nothing. Cells and calendar buckets keep their balls this way.
inline constexpr std::uint32_t kEndOfList = std::numeric_limits<std::uint32_t>::max();

/// Puts `ball` (in no list) first in the list that begins at `head`.
template <class Record>
void linkFirst(std::vector<Record>& records, std::uint32_t ball, std::uint32_t& head) {
  Record& record = records[ball];
  record.previous = kEndOfList;
  record.next = head;
  if (head != kEndOfList) records[head].previous = ball;
  head = ball;
}

/// Takes `ball` out of the list that begins at `head`.
template <class Record>
void unlink(std::vector<Record>& records, std::uint32_t ball, std::uint32_t& head) {
  const Record& record = records[ball];
  if (record.previous != kEndOfList) {
    records[record.previous].next = record.next;
  } else {
    head = record.next;
  }
  if (record.next != kEndOfList) records[record.next].previous = record.previous;
}

}  // namespace fooball::exact
