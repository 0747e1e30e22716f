#include "status_line.h"

#include <cstdio>

namespace fooball::cli {

void StatusLine::show(const std::string& text) {
  if (!enabled_) return;
  // Blank out what a longer previous line left behind.
  const std::size_t blanks = drawnWidth_ > text.size() ? drawnWidth_ - text.size() : 0;
  std::fprintf(stderr, "\r%s%*s", text.c_str(), static_cast<int>(blanks), "");
  std::fflush(stderr);
  drawnWidth_ = text.size();
}

void StatusLine::clear() {
  if (drawnWidth_ == 0) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(drawnWidth_), "");
  std::fflush(stderr);
  drawnWidth_ = 0;
}

}  // namespace fooball::cli
