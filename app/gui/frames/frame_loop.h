#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <functional>

#include "run/frame_rate.h"

class QTimer;
class QWidget;

namespace fooball::gui {

class RunController;
class RunFeed;

/// The window's frames: a ~60 Hz timer that turns elapsed real time (times the speed slider)
/// into physics steps; while the first of them runs, it draws the balls and feeds the charts
/// (every few frames) and the readouts and statistics (a few times a second) from the state
/// before it. --frames drives advance() itself.
class FrameLoop : public QObject {
  Q_OBJECT

 public:
  /// Steps `runs`, draws `view` and feeds `feed`; a child of `parent`.
  FrameLoop(RunController& runs, QWidget& view, RunFeed& feed, QObject* parent);

  /// One frame: the steps `elapsedSeconds` of real time hold, with the balls drawn and the
  /// samples, readouts and statistics that earlier frames made due shown (all from the state
  /// before the steps) while the first runs, or after the frame when it steps none. A frame's
  /// own steps make them due for the next frame.
  void advance(double elapsedSeconds);
  /// One frame of a recording: exactly `frameSeconds` of real time at the speed slider, i.e.
  /// frameSeconds·timeScale() simulated seconds, however long its steps take
  /// (RunController::advanceExactly); otherwise as advance(). The view is left to be drawn
  /// from the stepped state by whoever takes the frame.
  void advanceExactly(double frameSeconds);
  void start();
  /// While `framesPerSecond` > 0, the timer ticks at that rate and each tick is one
  /// advanceExactly(1/framesPerSecond) followed by `frameDone` (a recording takes its frame
  /// there); a machine too slow for the rate records slower than real time, never a frame
  /// with more simulated time in it. 0 goes back to real time.
  void setFixedFrameRate(double framesPerSecond, std::function<void()> frameDone = {});
  bool fixedFrameRate() const { return fixedFramesPerSecond_ > 0.0; }
  /// After a pause: the time paused is not caught up.
  void restartClock() { clock_.restart(); }
  /// The next sample comes kFramesPerSample frames from now (the charts have just been fed).
  void restartSampling() {
    framesSinceSample_ = 0;
    sampleDue_ = false;
  }

  /// Simulated seconds per real second (the speed slider).
  double timeScale() const { return timeScale_; }
  void setTimeScale(double timeScale) { timeScale_ = timeScale; }
  static constexpr double kDefaultTimeScale = 1.0;

  const FrameRate& frameRate() const { return frameRate_; }

 private:
  /// Counts a frame that took steps; every few, the charts, readouts or statistics fall due.
  void countSteppedFrame();
  /// Feeds what countSteppedFrame made due from the runs' current state.
  void showDueMeasurements();
  /// advance() and advanceExactly(): `stepRuns` runs the frame's steps with its argument to
  /// call while the first runs, and returns how many.
  void advanceWith(const std::function<int(const std::function<void()>&)>& stepRuns);

  RunController& runs_;
  QWidget& view_;
  RunFeed& feed_;
  QTimer* timer_;
  QElapsedTimer clock_;
  FrameRate frameRate_;
  double timeScale_ = kDefaultTimeScale;
  double fixedFramesPerSecond_ = 0.0;  ///< > 0 while recording (setFixedFrameRate)
  std::function<void()> frameDone_;
  int framesSinceSample_ = 0;
  int framesSinceReadout_ = 0;
  int framesSinceStatistics_ = 0;
  bool sampleDue_ = false;
  bool readoutDue_ = false;
  bool statisticsDue_ = false;
};

}  // namespace fooball::gui
