#include <QRadioButton>
#include <QStatusBar>

#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

/// One ball at rest at (4, 4.5) in an empty box, no gravity.
Scene oneBall() {
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {fooball::testing::ball({4.0, 4.5}, {0.0, 0.0})};
  return scene;
}

class MouseTools : public GuiTest {
 protected:
  void chooseMode(const char* radioName) {
    auto* radio = window->sidebar()->findChild<QRadioButton*>(QString::fromLatin1(radioName));
    ASSERT_NE(radio, nullptr) << radioName;
    radio->click();
  }
  Vec2 ball() const { return mainRun().positions()[0]; }
};

TEST_F(MouseTools, AttractPullsBallsTowardsTheCursor) {
  open(oneBall());
  chooseMode("attractRadio");
  const Vec2 cursor{10.0, 4.5};
  const double before = length(ball() - cursor);
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf(cursor));
  frames(20);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf(cursor));
  EXPECT_LT(length(ball() - cursor), before - 0.5);
}

TEST_F(MouseTools, SelectedScopeWithNothingSelectedSaysSoAndMovesNothing) {
  open(oneBall());
  chooseMode("attractRadio");
  chooseMode("selectedRadio");
  ASSERT_EQ(group().interactions().scope, Scope::Selected);
  ASSERT_FALSE(group().selected());
  const Vec2 cursor{10.0, 4.5};
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf(cursor));
  frames(20);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf(cursor));
  EXPECT_EQ(ball(), (Vec2{4.0, 4.5}));
  EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("none is selected")))
      << window->statusBar()->currentMessage().toStdString();
}

TEST_F(MouseTools, RepelPushesBallsAway) {
  open(oneBall());
  chooseMode("repelRadio");
  const Vec2 cursor{6.0, 4.5};
  const double before = length(ball() - cursor);
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf(cursor));
  frames(20);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf(cursor));
  EXPECT_GT(length(ball() - cursor), before + 0.5);
}

TEST_F(MouseTools, GrabCarriesTheNearestBallToTheCursor) {
  open(stillBalls());
  chooseMode("grabRadio");
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf({4.3, 4.4}));
  const Vec2 target{6.0, 2.0};
  QTest::mouseMove(view(), pixelOf({5.0, 3.0}));
  frames(5);
  QTest::mouseMove(view(), pixelOf(target));
  frames(60);
  EXPECT_LT(length(mainRun().positions()[0] - target), 0.1);
  EXPECT_EQ(mainRun().positions()[1], (Vec2{12.0, 4.5})) << "only the grabbed ball moves";
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf(target));
}

TEST_F(MouseTools, SlingshotLaunchesOppositeToThePull) {
  open(oneBall());
  chooseMode("slingshotRadio");
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf({4.0, 4.5}));
  QTest::mouseMove(view(), pixelOf({3.0, 3.5}));  // pulled back down-left
  frames(5);
  EXPECT_EQ(ball(), (Vec2{4.0, 4.5})) << "aiming only";
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf({3.0, 3.5}));
  frames(5);
  EXPECT_GT(mainRun().velocities()[0].x, 0.5);
  EXPECT_GT(mainRun().velocities()[0].y, 0.5);
  EXPECT_GT(ball().x, 4.0);
}

TEST_F(MouseTools, RightClickPlacesAPermanentAttractor) {
  open(oneBall());
  const Vec2 point{10.0, 4.5};
  QTest::mouseClick(view(), Qt::RightButton, {}, pixelOf(point));
  ASSERT_EQ(group().interactions().attractors().size(), 1u);
  EXPECT_NEAR(group().interactions().attractors()[0].x, point.x, 0.05);
  frames(20);
  EXPECT_GT(ball().x, 4.2) << "pulled towards the attractor with no button held";
}

TEST_F(MouseTools, ToolsActOnBothRunsInCompareMode) {
  open(oneBall(), "elastic", {"box2d"});
  chooseMode("attractRadio");
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf({10.0, 4.5}));
  frames(20);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf({10.0, 4.5}));
  EXPECT_GT(runs().run(0).positions()[0].x, 4.5);
  EXPECT_GT(runs().run(1).positions()[0].x, 4.5);
}

}  // namespace
}  // namespace fooball::gui::testing
