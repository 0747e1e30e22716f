#include "window/headless_run.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMenuBar>
#include <QPixmap>
#include <QStatusBar>
#include <csignal>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "charts/chart_panel.h"
#include "frames/run_feed.h"
#include "readouts/compare_readout.h"
#include "run/run_controller.h"
#include "view/simulation_view.h"
#include "window/main_window.h"

namespace fooball::gui {

namespace {

constexpr double kFrameSeconds = 1.0 / 60.0;  // physics per frame: one frame at 60 Hz
/// The window size of --frames runs and screenshots without --size, whatever the user's saved
/// layout.
constexpr QSize kHeadlessSize{1600, 1000};

/// Set by SIGINT or SIGTERM while recording: the video ends at the next frame, finished.
volatile std::sig_atomic_t interrupted = 0;

extern "C" void noteInterrupt(int) {
  interrupted = 1;
}

/// Only what is recorded on screen, so that the window's size is the video's: no menu, status
/// bar, settings, statistics or compare table; the charts only when recorded. Then the window
/// is sized until the area is exactly `size` (the charts' dock adds its title bar).
void showOnlyRecordedArea(MainWindow& window, RecordArea area, QSize size) {
  window.menuBar()->hide();
  window.statusBar()->hide();
  window.sidebarDock()->hide();
  window.statisticsDock()->hide();
  window.compareReadout()->hide();
  if (area == RecordArea::Box) window.chartsDock()->hide();
  window.resize(size);
  window.show();
  QApplication::processEvents();
  for (int attempt = 0; attempt < 4; ++attempt) {
    const QSize shown = RecordingFrameSource::shownSize(window.recordingTarget(), area);
    if (shown == size) break;
    window.resize(window.size() + (size - shown));
    QApplication::processEvents();
  }
}

std::string megabytes(qint64 bytes) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << double(bytes) / 1e6 << " MB";
  return text.str();
}

}  // namespace

int recordHeadless(MainWindow& window, const RecordingSettings& settings, int frames,
                   const std::optional<QString>& screenshotPath) {
  window.runs().setStepPatience(RunController::kWaitForEveryStep);
  showOnlyRecordedArea(window, settings.area, settings.size);
  std::optional<RecordingSession> session;
  try {
    session.emplace(window.recordingTarget(), settings);
  } catch (const video::VideoError& error) {
    std::cerr << "fooball: error: " << error.what() << '\n';
    return 1;
  }
  QString failure;
  QObject::connect(&*session, &RecordingSession::failed,
                   [&failure](const QString& message) { failure = message; });
  interrupted = 0;
  const auto previousInt = std::signal(SIGINT, noteInterrupt);
  const auto previousTerm = std::signal(SIGTERM, noteInterrupt);
  for (int i = 0; i < frames && !interrupted; ++i) {
    if (!session->recordNextFrame()) break;
    QApplication::processEvents();
  }
  std::signal(SIGINT, previousInt);
  std::signal(SIGTERM, previousTerm);
  if (failure.isEmpty()) failure = session->stop();
  if (!failure.isEmpty()) {
    std::cerr << "fooball: error: " << failure.toStdString() << '\n';
    return 1;
  }
  std::cout << std::fixed << std::setprecision(2) << "fooball: recorded " << session->frames()
            << " frames (" << session->seconds() << " s at " << settings.framesPerSecond
            << " frames/s, " << settings.size.width() << 'x' << settings.size.height() << ", "
            << session->codecName().toStdString() << ") to " << settings.path.toStdString() << ": "
            << megabytes(session->bytes()) << " in " << session->elapsedSeconds() << " s"
            << (interrupted ? " (interrupted)" : "") << '\n';
  if (screenshotPath && !session->lastFrame().save(*screenshotPath, "PNG")) {
    std::cerr << "fooball: error: could not write " << screenshotPath->toStdString() << '\n';
    return 1;
  }
  return interrupted ? 130 : 0;
}

int runHeadless(MainWindow& window, int frames, const std::optional<QString>& screenshotPath,
                const std::optional<QSize>& size) {
  // Every frame shows its steps: this is a measurement, not a window to keep responsive.
  window.runs().setStepPatience(RunController::kWaitForEveryStep);
  window.resize(size.value_or(kHeadlessSize));
  window.show();
  QApplication::processEvents();

  QElapsedTimer clock;
  qint64 totalNanoseconds = 0;
  for (int i = 0; i < frames; ++i) {
    clock.start();
    window.advanceFrame(kFrameSeconds);  // draws the balls while its step runs
    QApplication::processEvents();
    totalNanoseconds += clock.nsecsElapsed();
  }
  const double meanMs = double(totalNanoseconds) * 1e-6 / frames;
  const RunController& runs = window.runs();
  std::cout << std::fixed << std::setprecision(2) << "fooball: mean frame time " << meanMs
            << " ms (" << 1000.0 / meanMs << " frames/s) over " << frames << " frames, "
            << runs.group().ballCount() << " balls, "
            << runs.labels().join(QStringLiteral(" vs ")).toStdString() << '\n';

  if (screenshotPath) {
    // Everything of the moment the status bar shows: the readouts last refreshed frames ago.
    window.updateStatusBar();
    window.charts()->refresh();
    window.feed().showReadouts();
    window.feed().showStatistics();
    QApplication::processEvents();
    if (!window.grab().save(*screenshotPath, "PNG")) {
      std::cerr << "fooball: error: could not write " << screenshotPath->toStdString() << '\n';
      return 1;
    }
  }
  return 0;
}

}  // namespace fooball::gui
