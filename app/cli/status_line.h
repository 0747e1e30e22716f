#pragma once

#include <cstddef>
#include <string>

namespace fooball::cli {

/// One self-overwriting line of text on stderr ("\r") for commands that measure for minutes
/// (capacity, tradeoff). Drawn only when `enabled` (a terminal, not --quiet), so pipes and logs
/// never see it, and erased when done or destroyed.
class StatusLine {
 public:
  explicit StatusLine(bool enabled) : enabled_(enabled) {}
  ~StatusLine() { clear(); }
  StatusLine(const StatusLine&) = delete;
  StatusLine& operator=(const StatusLine&) = delete;

  void show(const std::string& text);
  void clear();

 private:
  bool enabled_;
  std::size_t drawnWidth_ = 0;  ///< characters on screen
};

}  // namespace fooball::cli
