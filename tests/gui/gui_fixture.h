#pragma once

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QPoint>
#include <QStringList>
#include <QtTest/QTest>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fooball/scene.h"
#include "run/run_controller.h"
#include "test_scenes.h"
#include "view/simulation_view.h"
#include "view/view_transform.h"
#include "widgets/user_messages.h"
#include "window/main_window.h"

namespace fooball::gui::testing {

inline constexpr double kFrame = 1.0 / 60.0;  // s, one frame of physics

/// A main window on `scene` that neither reads nor writes the user's settings, records errors
/// instead of showing message boxes, and waits for every step.
class GuiTest : public ::testing::Test {
 protected:
  /// `backend` and each of `compare` are run specs ("elastic", "box2d:substeps=8").
  void open(const Scene& scene, const std::string& backend = "elastic",
            const std::vector<std::string>& compare = {}) {
    StartupOptions options;
    options.scene = scene;
    options.sourceName = QStringLiteral("test");
    options.runs = {parseRunSpec(backend)};
    for (const std::string& spec : compare)
      options.runs.push_back(parseRunSpec(spec));
    options.rememberSettings = false;
    window = std::make_unique<MainWindow>(options);
    window->messages().setErrorReporter(
        [this](const QString&, const QString& message) { errors.append(message); });
    // Every step waited for, as in a headless run, so a test does the same on any machine,
    // however loaded; slow_step_test.cpp tests the steps left to run in the background.
    runs().setStepPatience(RunController::kWaitForEveryStep);
    window->resize(1280, 800);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  }

  RunController& runs() const { return window->runs(); }
  const Simulation& mainRun() const { return runs().run(0); }
  const RunGroup& group() const { return runs().group(); }
  SimulationView* view() const { return window->view(); }

  /// The view pixel showing `point` (m) in run `runIndex`'s box.
  QPoint pixelOf(Vec2 point, int runIndex = 0) const {
    return view()->transformForRun(runIndex).toPixels(point).toPoint();
  }

  void frames(int count) {
    for (int i = 0; i < count; ++i)
      window->advanceFrame(kFrame);
  }

  std::unique_ptr<MainWindow> window;
  QStringList errors;
};

/// Sanitizers slow the measured steps several-fold; the bounds on wall time allow for it.
inline double slowdown() {
  return qEnvironmentVariableIsSet("FOOBALL_SANITIZED") ? 5.0 : 1.0;
}

/// Processes events until `done` or `seconds` pass, sleeping 10 ms between looks (QTest::qWaitFor);
/// whether `done` came true. A loop of processEvents alone returns at once when no event waits,
/// so it kept a core busy that the worker it waited for, or the test beside it, wanted.
inline bool waitUntil(const std::function<bool()>& done, double seconds) {
  return QTest::qWaitFor(done, static_cast<int>(1000.0 * seconds));
}

/// A few still balls, well apart, in a 16 × 9 m box without gravity.
inline Scene stillBalls() {
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {fooball::testing::ball({4.0, 4.5}, {0.0, 0.0}),
                 fooball::testing::ball({12.0, 4.5}, {0.0, 0.0}),
                 fooball::testing::ball({8.0, 7.5}, {0.0, 0.0})};
  return scene;
}

}  // namespace fooball::gui::testing
