#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace fooball::cli {

/// One self-overwriting line on stderr ("\r") showing how far a long run is: percentage,
/// simulated time, steps/s and the time left. It appears only once the run has taken more than
/// a second, redraws a few times a second, and is erased when the run ends (or throws), so short
/// runs, pipes and log files never see it.
class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  /// `enabled` is false for --quiet or when stderr is not a terminal.
  ProgressLine(bool enabled, std::uint64_t totalSteps);
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// `stepsDone` of the total, at `simulatedTime` seconds.
  void update(std::uint64_t stepsDone, double simulatedTime);

  /// Erases the line, if it was drawn.
  void clear();

  /// Whether stderr is a terminal, i.e. whether a progress line would be seen.
  static bool stderrIsTerminal();

 private:
  bool enabled_;
  std::uint64_t totalSteps_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastDrawn_;
  std::size_t drawnWidth_ = 0;  ///< characters on screen, 0 when nothing is shown
};

}  // namespace fooball::cli
