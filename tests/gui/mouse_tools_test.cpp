#include <QImage>
#include <QRadioButton>
#include <QStatusBar>

#include "chart_reading.h"
#include "charts/chart_panel.h"
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
  EXPECT_TRUE(window->messages().status().contains(QStringLiteral("none is selected")))
      << window->messages().status().toStdString();
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

TEST_F(MouseTools, ClicksInTheCaptionRowsAreNoToolUse) {
  open(oneBall(), "elastic", {"box2d"});  // two legend entries above the box
  chooseMode("slingshotRadio");
  const auto captions = view()->captions();
  ASSERT_FALSE(captions.empty());
  const int markers = markerCount(*window->charts());
  const int boxTop = pixelOf({0.0, fooball::testing::emptyBox().box.height}).y();
  ASSERT_GT(boxTop, 4);
  std::vector<QPoint> clicks{QPoint(view()->width() / 2, boxTop - 2)};
  for (const SimulationView::Caption& caption : captions)
    clicks.push_back(caption.rect.center());
  for (const QPoint click : clicks) {
    QTest::mousePress(view(), Qt::LeftButton, {}, click);
    EXPECT_FALSE(group().interactions().pressed()) << click.x() << ", " << click.y();
    QTest::mouseRelease(view(), Qt::LeftButton, {}, click);
  }
  frames(5);
  EXPECT_EQ(markerCount(*window->charts()), markers) << "no slingshot marker";
  EXPECT_EQ(ball(), (Vec2{4.0, 4.5}));
  // The box itself still takes the tool.
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf({6.0, 4.5}));
  EXPECT_TRUE(group().interactions().pressed());
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf({6.0, 4.5}));
}

TEST_F(MouseTools, SlingshotTakesTheBallUnderTheCursorAndRingsIt) {
  // A big ball, and a small one whose centre is nearer the press than the big one's.
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {fooball::testing::ball({5.0, 4.5}, {0.0, 0.0}, 2.0),
                 fooball::testing::ball({8.3, 4.5}, {0.0, 0.0}, 0.1)};
  open(scene);
  chooseMode("slingshotRadio");
  ASSERT_EQ(group().interactions().scope, Scope::All);
  const Vec2 press{6.9, 4.5};
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf(press));
  ASSERT_EQ(mainRun().interactions.target(), std::optional<std::size_t>(0))
      << "the ball under the cursor, not the nearest centre";
  const QImage shot = view()->grab().toImage();
  // Above the big ball, just outside it: the ring (the aim line runs along y = 4.5).
  const ViewTransform t = view()->transformForRun(0);
  const QPointF ringTop = t.toPixels(Vec2{5.0, 4.5}) - QPointF(0.0, t.toPixels(2.0) + 4.0);
  const QColor atRing = shot.pixelColor(ringTop.toPoint() * shot.devicePixelRatio());
  EXPECT_GT(atRing.lightness(), 60) << "ringed: " << atRing.name().toStdString();
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf({6.0, 4.5}));
  frames(3);
  EXPECT_GT(mainRun().velocities()[0].x, 0.0) << "pulled left, the big ball flies right";
  EXPECT_EQ(mainRun().velocities()[1], (Vec2{0.0, 0.0}));
}

}  // namespace
}  // namespace fooball::gui::testing
