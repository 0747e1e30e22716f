// Rewind in the window: while paused, Step back (',') and the timeline under the box take every
// run back to a kept moment; the view and the charts show that time, and continuing drops the
// charts' future. The engine's guarantee (bit for bit) is tests/rewind_test.cpp's.

#include <QSlider>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "readouts/timeline_bar.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

/// 30 balls falling under gravity: the state changes every step.
Scene fallingBalls() {
  Scene scene = fooball::testing::gas(30);
  scene.world.gravity = {0.0, -9.81};
  return scene;
}

class RewindInWindow : public GuiTest {
 protected:
  /// s, the time of the last sample run 0's charts plot (after a refresh).
  double lastChartTime() const {
    window->charts()->refresh();
    const QList<QPointF> points = displayedPoints(*window->charts(), 0, 0);
    return points.isEmpty() ? -1.0 : points.back().x();
  }
};

TEST_F(RewindInWindow, StepBackShowsAnEarlierTimeAndContinuingDropsTheChartsFuture) {
  open(fallingBalls());
  frames(60);  // 1 s: moments every 0.1 s
  QTest::keyClick(view(), Qt::Key_Space);
  ASSERT_TRUE(runs().paused());
  const double now = group().time();
  EXPECT_NEAR(lastChartTime(), now, 0.1);  // charts sample every few frames

  QTest::keyClick(view(), Qt::Key_Comma);
  QTest::keyClick(view(), Qt::Key_Comma);
  const double rewound = group().time();
  EXPECT_NEAR(rewound, 0.8, 1e-9);  // moments every 0.1 s: 1.0 s is now, 0.9, then 0.8
  EXPECT_DOUBLE_EQ(lastChartTime(), rewound);

  QTest::keyClick(view(), Qt::Key_Space);  // continue: the future goes
  frames(6);
  EXPECT_NEAR(group().time(), rewound + 0.1, 1e-9);
  EXPECT_NEAR(lastChartTime(), group().time(), 0.1);
  EXPECT_LE(lastChartTime(), group().time());
  EXPECT_EQ(group().history()->size(), 10u);  // 0 to 0.8 s, then 0.9 s anew
}

TEST_F(RewindInWindow, TheTimelineRewindsWhilePausedAndShowsTheBound) {
  open(fallingBalls());
  QSlider* timeline = window->timeline().slider();
  frames(30);
  window->timeline().showHistory();
  EXPECT_FALSE(timeline->isEnabled());  // running: nothing to scrub
  QTest::keyClick(view(), Qt::Key_Space);
  ASSERT_TRUE(timeline->isEnabled());
  EXPECT_EQ(timeline->maximum(), 5);  // moments at 0, 0.1, … 0.5 s
  EXPECT_EQ(window->timeline().text(), QStringLiteral("history 0.5 s, 0.0/256 MB"));

  timeline->setFocus();
  QTest::keyClick(timeline, Qt::Key_Home);  // to the first moment
  EXPECT_EQ(group().time(), 0.0);
  EXPECT_DOUBLE_EQ(lastChartTime(), 0.0);
  const Vec2 start = mainRun().positions()[0];
  EXPECT_EQ(start, fallingBalls().balls[0].position);
  QTest::keyClick(timeline, Qt::Key_Right);
  EXPECT_NEAR(group().time(), 0.1, 1e-9);
}

}  // namespace
}  // namespace fooball::gui::testing
