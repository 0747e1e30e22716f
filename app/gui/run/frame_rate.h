#pragma once

#include <QElapsedTimer>
#include <algorithm>

namespace fooball::gui {

/// Frames and physics steps per second of wall time, measured over windows of half a second so
/// the status bar shows steady numbers.
class FrameRate {
 public:
  FrameRate() { window_.start(); }

  void addFrame(int steps) {
    ++frames_;
    steps_ += steps;
    const qint64 elapsed = window_.nsecsElapsed();
    if (elapsed < kWindowNanoseconds) return;
    const double windowSeconds = double(elapsed) * 1e-9;
    framesPerSecond_ = frames_ / windowSeconds;
    stepsPerSecond_ = steps_ / windowSeconds;
    measured_ = true;
    frames_ = 0;
    steps_ = 0;
    window_.restart();
  }

  /// Over the last whole window, or over what there is until the first window is complete.
  double framesPerSecond() const { return measured_ ? framesPerSecond_ : frames_ / seconds(); }
  double stepsPerSecond() const { return measured_ ? stepsPerSecond_ : steps_ / seconds(); }

 private:
  static constexpr qint64 kWindowNanoseconds = 500'000'000;
  double seconds() const { return std::max(double(window_.nsecsElapsed()) * 1e-9, 1e-9); }

  QElapsedTimer window_;
  double frames_ = 0;
  double steps_ = 0;
  double framesPerSecond_ = 0.0;
  double stepsPerSecond_ = 0.0;
  bool measured_ = false;  ///< a whole window has passed
};

}  // namespace fooball::gui
