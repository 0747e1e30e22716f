#include "progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

namespace fooball::cli {

namespace {

/// Runs shorter than this finish before a progress line would help.
constexpr auto kQuietStart = std::chrono::seconds(1);
/// Redrawing more often only costs time and flickers.
constexpr auto kRedrawInterval = std::chrono::milliseconds(250);

/// "42 s", "3:07" or "1:02:07".
std::string durationText(double seconds) {
  const auto whole = static_cast<long long>(seconds + 0.5);
  std::array<char, 32> text{};
  if (whole < 60) {
    std::snprintf(text.data(), text.size(), "%lld s", whole);
  } else if (whole < 3600) {
    std::snprintf(text.data(), text.size(), "%lld:%02lld", whole / 60, whole % 60);
  } else {
    std::snprintf(text.data(), text.size(), "%lld:%02lld:%02lld", whole / 3600, whole / 60 % 60,
                  whole % 60);
  }
  return text.data();
}

}  // namespace

ProgressLine::ProgressLine(bool enabled, std::uint64_t totalSteps)
    : enabled_(enabled && totalSteps > 0), totalSteps_(totalSteps) {}

bool ProgressLine::stderrIsTerminal() {
  return isatty(STDERR_FILENO) == 1;
}

void ProgressLine::update(std::uint64_t stepsDone, double simulatedTime) {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  if (now - start_ < kQuietStart || now - lastDrawn_ < kRedrawInterval) return;
  lastDrawn_ = now;

  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = static_cast<double>(stepsDone) / static_cast<double>(totalSteps_);
  const double stepsPerSecond = static_cast<double>(stepsDone) / elapsed;
  const double secondsLeft =
      stepsPerSecond > 0.0 ? static_cast<double>(totalSteps_ - stepsDone) / stepsPerSecond : 0.0;

  std::array<char, 128> line{};
  std::snprintf(line.data(), line.size(), "\r%5.1f%%  t = %.4g s  %.0f steps/s  ETA %s",
                100.0 * fraction, simulatedTime, stepsPerSecond, durationText(secondsLeft).c_str());
  std::string text = line.data();
  const std::size_t width = text.size() - 1;
  // Blank out what a longer previous line left behind.
  text.append(drawnWidth_ > width ? drawnWidth_ - width : 0, ' ');
  drawnWidth_ = std::max(drawnWidth_, width);
  std::fputs(text.c_str(), stderr);
  std::fflush(stderr);
}

void ProgressLine::clear() {
  if (drawnWidth_ == 0) return;
  std::string blank(drawnWidth_ + 2, ' ');
  blank.front() = '\r';
  blank.back() = '\r';
  std::fputs(blank.c_str(), stderr);
  std::fflush(stderr);
  drawnWidth_ = 0;
}

}  // namespace fooball::cli
