#include "stderr_tail.h"

namespace fooball::node_host {

void StderrTail::append(std::string_view bytes) {
  for (const char byte : bytes) {
    ring_[next_] = byte;
    next_ = (next_ + 1) % kCapacity;
    wrapped_ = wrapped_ || next_ == 0;
  }
}

std::string StderrTail::text() const {
  std::string kept;
  if (wrapped_) {
    kept.assign(ring_ + next_, kCapacity - next_);
    kept.append(ring_, next_);
    const std::size_t lineStart = kept.find('\n');
    if (lineStart != std::string::npos) kept.erase(0, lineStart + 1);
  } else {
    kept.assign(ring_, next_);
  }
  const std::size_t end = kept.find_last_not_of(" \t\r\n");
  kept.resize(end == std::string::npos ? 0 : end + 1);
  return kept;
}

}  // namespace fooball::node_host
