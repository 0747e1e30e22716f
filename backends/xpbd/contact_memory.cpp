#include "contact_memory.h"

#include <algorithm>

namespace fooball::xpbd {

void ContactMemory::reset(std::size_t balls) {
  balls_ = static_cast<std::uint32_t>(balls);
  start_.assign(balls + 1, 0u);
  start_.shrink_to_fit();
  entries_.clear();
  fresh_.clear();
}

bool ContactMemory::recall(std::uint32_t first, std::uint32_t second, std::uint32_t now) {
  // A ball has a handful of partners: a linear scan of its row.
  for (std::uint32_t k = start_[first]; k < start_[first + 1]; ++k) {
    Entry& entry = entries_[k];
    if (entry.second == second) {
      // Unsigned difference: right across the wrap of the substep count.
      const bool recent = now - entry.stamp <= kContactMemory;
      if (recent) entry.stamp = now;
      return recent;
    }
  }
  return false;
}

void ContactMemory::commit(std::uint32_t now) {
  if (entries_.empty() && fresh_.empty()) return;
  // The kept entries: those still within the memory after this substep.
  const auto kept = [&](const Entry& entry) { return now - entry.stamp < kContactMemory; };
  // Count each ball's partners into start_[ball + 1]; the rows of entries_ give the first ball.
  scratch_.clear();
  for (std::uint32_t ball = 0; ball < balls_; ++ball) {
    const std::uint32_t end = start_[ball + 1];
    for (std::uint32_t k = start_[ball]; k < end; ++k) {
      if (kept(entries_[k])) scratch_.push_back({ball, entries_[k].second, entries_[k].stamp});
    }
  }
  for (Entry& entry : fresh_) {
    entry.stamp = now;
    scratch_.push_back(entry);
  }
  fresh_.clear();
  std::fill(start_.begin(), start_.end(), 0u);
  for (const Entry& entry : scratch_)
    ++start_[entry.first + 1];
  for (std::size_t ball = 1; ball < start_.size(); ++ball)
    start_[ball] += start_[ball - 1];
  entries_.resize(scratch_.size());
  // Scatter with start_[first] as the cursor, then shift the cursors back by one row.
  for (const Entry& entry : scratch_)
    entries_[start_[entry.first]++] = entry;
  for (std::size_t ball = start_.size() - 1; ball > 0; --ball)
    start_[ball] = start_[ball - 1];
  start_[0] = 0;
}

std::size_t ContactMemory::memoryBytes() const {
  return start_.capacity() * sizeof(std::uint32_t) +
         (entries_.capacity() + scratch_.capacity() + fresh_.capacity()) * sizeof(Entry);
}

}  // namespace fooball::xpbd
