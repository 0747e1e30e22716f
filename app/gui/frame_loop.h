#pragma once

#include <QElapsedTimer>
#include <QObject>

#include "frame_rate.h"

class QTimer;

namespace fooball::gui {

class MainWindow;

/// The window's frames: a ~60 Hz timer that turns elapsed real time (times the speed slider)
/// into physics steps, draws the balls while the first of them runs, feeds the charts every few
/// frames and the readouts and statistics a few times a second. --frames drives advance()
/// itself.
class FrameLoop : public QObject {
  Q_OBJECT

 public:
  explicit FrameLoop(MainWindow& window);

  /// One frame: the steps `elapsedSeconds` of real time hold, with the balls drawn (the state
  /// before them) while the first runs, or after the frame when it steps none; samples,
  /// readouts.
  void advance(double elapsedSeconds);
  void start();
  /// After a pause: the time paused is not caught up.
  void restartClock() { clock_.restart(); }
  /// The next sample comes kFramesPerSample frames from now.
  void restartSampling() { framesSinceSample_ = 0; }

  /// Simulated seconds per real second (the speed slider).
  double timeScale() const { return timeScale_; }
  void setTimeScale(double timeScale) { timeScale_ = timeScale; }
  static constexpr double kDefaultTimeScale = 1.0;

  const FrameRate& frameRate() const { return frameRate_; }

 private:
  MainWindow& window_;
  QTimer* timer_;
  QElapsedTimer clock_;
  FrameRate frameRate_;
  double timeScale_ = kDefaultTimeScale;
  int framesSinceSample_ = 0;
  int framesSinceReadout_ = 0;
  int framesSinceStatistics_ = 0;
};

}  // namespace fooball::gui
