#include "headless_run.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QPixmap>
#include <iomanip>
#include <iostream>

#include "charts/chart_panel.h"
#include "main_window.h"
#include "run_controller.h"
#include "simulation_view.h"

namespace fooball::gui {

namespace {

constexpr double kFrameSeconds = 1.0 / 60.0;  // physics per frame: one frame at 60 Hz
/// The window size of --frames runs and screenshots without --size, whatever the user's saved
/// layout.
constexpr QSize kDefaultSize{1600, 1000};

}  // namespace

int runHeadless(MainWindow& window, int frames, const std::optional<QString>& screenshotPath,
                const std::optional<QSize>& size) {
  // Every frame shows its steps: this is a measurement, not a window to keep responsive.
  window.runs().setStepPatience(RunController::kWaitForEveryStep);
  window.resize(size.value_or(kDefaultSize));
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
    window.updateStatusBar();
    window.charts()->refresh();
    window.showStatistics();
    QApplication::processEvents();
    if (!window.grab().save(*screenshotPath, "PNG")) {
      std::cerr << "fooball: error: could not write " << screenshotPath->toStdString() << '\n';
      return 1;
    }
  }
  return 0;
}

}  // namespace fooball::gui
