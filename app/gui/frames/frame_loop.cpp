#include "frames/frame_loop.h"

#include <QTimer>
#include <algorithm>
#include <cmath>
#include <utility>

#include "frames/run_feed.h"
#include "run/run_controller.h"
#include "view/simulation_view.h"

namespace fooball::gui {

namespace {

constexpr int kFrameIntervalMs = 16;      // ~60 frames/s
constexpr double kMaxFrameSeconds = 0.1;  // a stall longer than this is not caught up
/// Charts get a sample every few frames: 20 per second at 60 frames/s is smooth, and keeps
/// the O(N) energy and momentum sums off most frames at 100,000 balls.
constexpr int kFramesPerSample = 3;
constexpr int kFramesPerReadout = 6;  // compare readout and inspector: 10 per second
/// The statistics dock, while open: 4 per second. Its histogram and KS sort cost about a
/// millisecond at 10,000 balls, so this keeps them to a few percent of the frames.
constexpr int kFramesPerStatistics = 15;

}  // namespace

FrameLoop::FrameLoop(RunController& runs, QWidget& view, RunFeed& feed, QObject* parent)
    : QObject(parent), runs_(runs), view_(view), feed_(feed) {
  timer_ = new QTimer(this);
  timer_->setTimerType(Qt::PreciseTimer);
  timer_->setInterval(kFrameIntervalMs);
  connect(timer_, &QTimer::timeout, this, [this] {
    const double elapsed = std::min(double(clock_.nsecsElapsed()) * 1e-9, kMaxFrameSeconds);
    clock_.restart();
    if (fixedFramesPerSecond_ > 0.0) {
      advanceExactly(1.0 / fixedFramesPerSecond_);
      if (frameDone_) frameDone_();
    } else {
      advance(elapsed);
    }
  });
}

void FrameLoop::setFixedFrameRate(double framesPerSecond, std::function<void()> frameDone) {
  fixedFramesPerSecond_ = framesPerSecond > 0.0 ? framesPerSecond : 0.0;
  frameDone_ = fixedFramesPerSecond_ > 0.0 ? std::move(frameDone) : std::function<void()>();
  timer_->setInterval(fixedFramesPerSecond_ > 0.0 ? int(std::lround(1000.0 / fixedFramesPerSecond_))
                                                  : kFrameIntervalMs);
  clock_.restart();
}

void FrameLoop::advance(double elapsedSeconds) {
  advanceWith([&](const std::function<void()>& whileFirstStepRuns) {
    return runs_.advance(elapsedSeconds, timeScale_, whileFirstStepRuns);
  });
}

void FrameLoop::advanceExactly(double frameSeconds) {
  advanceWith([&](const std::function<void()>& whileFirstStepRuns) {
    return runs_.advanceExactly(frameSeconds * timeScale_, whileFirstStepRuns);
  });
}

void FrameLoop::advanceWith(const std::function<int(const std::function<void()>&)>& stepRuns) {
  // While the frame's first step runs, the window's thread feeds the charts, readouts and
  // statistics that earlier frames made due and draws the balls (the state before the step,
  // carried ahead over the steps' time): all of them read the state the last steps left, which
  // the workers do not touch until the step is collected. Done after the step instead, the
  // window's thread would wait for it and then work alone; at 100'000 balls the two take about
  // as long.
  bool overlapped = false;
  const int steps = stepRuns([&] {
    showDueMeasurements();
    view_.repaint();
    overlapped = true;
  });
  frameRate_.addFrame(steps);
  if (steps > 0) countSteppedFrame();
  if (!overlapped) {
    // No step ran beside this frame (paused, or a slow step collected): nothing to wait for.
    showDueMeasurements();
    view_.update();
  }
}

void FrameLoop::countSteppedFrame() {
  if (++framesSinceSample_ >= kFramesPerSample) {
    framesSinceSample_ = 0;
    sampleDue_ = true;
  }
  if (++framesSinceReadout_ >= kFramesPerReadout) {
    framesSinceReadout_ = 0;
    readoutDue_ = true;
  }
  if (++framesSinceStatistics_ >= kFramesPerStatistics) {
    framesSinceStatistics_ = 0;
    statisticsDue_ = true;
  }
}

void FrameLoop::showDueMeasurements() {
  if (std::exchange(sampleDue_, false)) feed_.sampleCharts();
  if (std::exchange(readoutDue_, false)) {
    feed_.showReadouts();
    if (runs_.group().selected()) feed_.showSelectedBall();
  }
  if (std::exchange(statisticsDue_, false)) feed_.showStatistics();
}

void FrameLoop::start() {
  clock_.start();
  timer_->start();
}

}  // namespace fooball::gui
