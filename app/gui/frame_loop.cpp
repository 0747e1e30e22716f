#include "frame_loop.h"

#include <QTimer>
#include <algorithm>

#include "main_window.h"
#include "run_controller.h"
#include "simulation_view.h"

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

FrameLoop::FrameLoop(MainWindow& window) : QObject(&window), window_(window) {
  timer_ = new QTimer(this);
  timer_->setTimerType(Qt::PreciseTimer);
  timer_->setInterval(kFrameIntervalMs);
  connect(timer_, &QTimer::timeout, this, [this] {
    const double elapsed = std::min(double(clock_.nsecsElapsed()) * 1e-9, kMaxFrameSeconds);
    clock_.restart();
    advance(elapsed);
  });
}

void FrameLoop::advance(double elapsedSeconds) {
  RunController& runs = window_.runs();
  // The balls are drawn while the frame's first step runs: the state before it, carried ahead
  // over the steps' time. The window's thread would otherwise wait for the step, then draw, and
  // the two take about as long at 100'000 balls. Drawn now, they are not drawn again below: the
  // next frame draws the state these steps leave.
  bool drawn = false;
  const int steps = runs.advance(elapsedSeconds, timeScale_, [&] {
    window_.view()->repaint();
    drawn = true;
  });
  frameRate_.addFrame(steps);
  if (steps > 0) {
    if (++framesSinceSample_ >= kFramesPerSample) {
      framesSinceSample_ = 0;
      window_.sampleCharts();
    }
    if (++framesSinceReadout_ >= kFramesPerReadout) {
      framesSinceReadout_ = 0;
      window_.showReadouts();
      if (runs.group().selected()) window_.showSelectedBall();
    }
    if (++framesSinceStatistics_ >= kFramesPerStatistics) {
      framesSinceStatistics_ = 0;
      window_.showStatistics();
    }
  }
  if (!drawn) window_.view()->update();
}

void FrameLoop::start() {
  clock_.start();
  timer_->start();
}

}  // namespace fooball::gui
