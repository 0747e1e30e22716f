#include <QCheckBox>
#include <QSlider>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/log_slider.h"
#include "widgets/number_format.h"

namespace fooball::gui::testing {
namespace {

class Sliders : public GuiTest {
 protected:
  /// Moves `slider` to `position` as a user would, returning the value it now shows.
  static double move(LogSlider* slider, int position) {
    slider->slider()->setValue(position);
    return slider->value();
  }
};

TEST_F(Sliders, GravitySliderSetsWorldGravityDownwards) {
  open(stillBalls());
  LogSlider* gravity = window->sidebar()->gravitySlider();
  const double chosen = move(gravity, gravity->positionOf(9.81));
  EXPECT_NEAR(chosen, 9.81, 0.2);
  EXPECT_DOUBLE_EQ(group().world().gravity.x, 0.0);
  EXPECT_DOUBLE_EQ(group().world().gravity.y, -chosen);
  frames(10);
  EXPECT_LT(mainRun().velocities()[0].y, 0.0) << "the balls fall";
}

TEST_F(Sliders, OneDragIsOneMarkerShowingTheFinalValue) {
  open(stillBalls());
  LogSlider* gravity = window->sidebar()->gravitySlider();
  const int before = markerCount(*window->charts());
  // A drag sends a value every few milliseconds.
  for (int position = 100; position <= 400; position += 10)
    move(gravity, position);
  ASSERT_EQ(markerCount(*window->charts()), before + 1) << "one gesture, one marker";
  const QString label = markerLabels(*window->charts()).back();
  EXPECT_TRUE(label.contains(formatNumber(gravity->value()))) << label.toStdString();
  // A change seconds later is a gesture of its own; another setting is one anyway.
  QTest::qWait(800);
  move(gravity, 450);
  EXPECT_EQ(markerCount(*window->charts()), before + 2);
  move(window->sidebar()->airResistanceSlider(), 300);
  EXPECT_EQ(markerCount(*window->charts()), before + 3);
}

TEST_F(Sliders, GravitySliderLeftEndIsExactlyZero) {
  Scene scene = stillBalls();
  scene.world.gravity = {0.0, -9.81};
  open(scene);
  move(window->sidebar()->gravitySlider(), 0);
  EXPECT_EQ(group().world().gravity, (Vec2{0.0, 0.0}));
}

TEST_F(Sliders, GravitySliderKeepsTheScenesDirection) {
  Scene scene = stillBalls();
  scene.world.gravity = {3.0, 4.0};
  open(scene);
  LogSlider* gravity = window->sidebar()->gravitySlider();
  const double chosen = move(gravity, gravity->positionOf(10.0));
  EXPECT_NEAR(group().world().gravity.x, 0.6 * chosen, 1e-12);
  EXPECT_NEAR(group().world().gravity.y, 0.8 * chosen, 1e-12);
}

TEST_F(Sliders, AirResistanceSliderSetsDragInEveryRun) {
  open(stillBalls(), "elastic", {"box2d"});
  LogSlider* drag = window->sidebar()->airResistanceSlider();
  const double chosen = move(drag, drag->positionOf(0.5));
  EXPECT_GT(chosen, 0.0);
  EXPECT_DOUBLE_EQ(runs().run(0).world().airResistance, chosen);
  EXPECT_DOUBLE_EQ(runs().run(1).world().airResistance, chosen);
}

TEST_F(Sliders, StrengthSliderSetsMouseStrength) {
  open(stillBalls());
  LogSlider* strength = window->sidebar()->strengthSlider();
  const double chosen = move(strength, LogSlider::kPositions);
  EXPECT_DOUBLE_EQ(chosen, 1000.0);
  EXPECT_DOUBLE_EQ(group().interactions().strength, 1000.0);
  move(strength, 0);
  EXPECT_DOUBLE_EQ(group().interactions().strength, 0.0);
}

TEST_F(Sliders, SpeedSliderRightIsFaster) {
  open(stillBalls());
  LogSlider* speed = window->sidebar()->timeScaleSlider();
  move(speed, speed->positionOf(1.0));
  frames(30);
  const double slow = mainRun().time();
  move(speed, speed->positionOf(2.0));
  frames(30);
  EXPECT_NEAR(mainRun().time() - slow, 2.0 * slow, 2.0 * kFrame);
}

TEST_F(Sliders, ResetSlidersRestoresTheScenesValues) {
  Scene scene = stillBalls();
  scene.world.gravity = {0.0, -9.81};
  scene.world.airResistance = 0.1;
  open(scene);
  move(window->sidebar()->gravitySlider(), 0);
  move(window->sidebar()->airResistanceSlider(), LogSlider::kPositions);
  move(window->sidebar()->strengthSlider(), 0);
  emit window->sidebar()->resetSlidersRequested();
  EXPECT_EQ(group().world().gravity, scene.world.gravity);
  EXPECT_EQ(group().world().airResistance, 0.1);
  EXPECT_EQ(group().interactions().strength, 10.0);
  EXPECT_DOUBLE_EQ(window->sidebar()->gravitySlider()->value(), 9.81);
}

TEST_F(Sliders, CollisionAndWallBoxesSetTheWorld) {
  open(stillBalls());
  window->sidebar()->findChild<QCheckBox*>(QStringLiteral("ballCollisionsBox"))->click();
  EXPECT_FALSE(group().world().ballCollisions);
  window->sidebar()->findChild<QCheckBox*>(QStringLiteral("leftWallBox"))->click();
  EXPECT_EQ(group().world().walls, (Walls{false, true, true, true}));
  window->sidebar()->findChild<QCheckBox*>(QStringLiteral("topWallBox"))->click();
  EXPECT_EQ(group().world().walls, (Walls{false, true, true, false}));
}

TEST_F(Sliders, ExtremeSettingsKeepEveryBall) {
  open(fooball::testing::gas(200));
  move(window->sidebar()->gravitySlider(), LogSlider::kPositions);
  move(window->sidebar()->strengthSlider(), LogSlider::kPositions);
  move(window->sidebar()->airResistanceSlider(), LogSlider::kPositions);
  move(window->sidebar()->timeScaleSlider(), LogSlider::kPositions);
  QTest::mousePress(view(), Qt::LeftButton, {}, pixelOf({8.0, 4.5}));
  frames(20);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, pixelOf({8.0, 4.5}));
  move(window->sidebar()->gravitySlider(), 0);
  frames(20);
  const Metrics metrics = mainRun().metrics();
  EXPECT_EQ(mainRun().ballCount(), 200u);
  EXPECT_EQ(metrics.escaped, 0u);
  for (const Vec2 p : mainRun().positions())
    EXPECT_TRUE(isFinite(p));
}

}  // namespace
}  // namespace fooball::gui::testing
