// Slow motion is smooth: at 0.05× a physics step is due only every 20 frames, yet the view
// draws the balls where they are between steps (the stepped state carried ahead by the
// simulated time not stepped yet), so they move every frame. The physics is untouched: the same
// steps, and while paused the view shows the stepped state exactly.
//
// A frame draws the balls while its first step runs: the state before the step, carried over
// the step's time too. What the frame itself drew (no repaint after it) moves as smoothly.

#include <QSlider>
#include <vector>

#include "frames/frame_loop.h"
#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/log_slider.h"

namespace fooball::gui::testing {
namespace {

using fooball::testing::ball;

constexpr Vec2 kVelocity{3.0, 0.0};  // m/s

class SmoothMotion : public GuiTest {
 protected:
  /// One ball crossing an empty box, far from everything for the whole test.
  void openCrossingBall() {
    Scene scene = fooball::testing::emptyBox();
    scene.balls = {ball({4.0, 4.5}, kVelocity, 0.3)};
    open(scene);
  }

  /// Where the view draws ball 0 after one more frame of real time (a synchronous repaint).
  Vec2 drawnAfterFrame() {
    window->advanceFrame(kFrame);
    view()->repaint();
    return view()->drawnPositions(0)[0];
  }
};

TEST_F(SmoothMotion, AtTheSlowestSpeedTheBallMovesEveryFrameWhileOneStepIsTaken) {
  openCrossingBall();
  LogSlider* speed = window->sidebar()->timeScaleSlider();
  QTest::keyClick(speed->slider(), Qt::Key_Home);
  ASSERT_EQ(window->frames().timeScale(), 0.05);
  view()->repaint();
  const std::uint64_t stepsBefore = group().steps();
  Vec2 previous = view()->drawnPositions(0)[0];
  ASSERT_EQ(previous, mainRun().positions()[0]) << "nothing pending yet";
  // Each frame of 1/60 s holds 0.05/60 s of simulated time: the ball is drawn that much of its
  // flight further on, v·0.05/60 = 2.5 mm, in every frame, the step's frame included.
  const double perFrame = kVelocity.x * 0.05 * kFrame;
  for (int frame = 1; frame <= 20; ++frame) {
    const Vec2 drawn = drawnAfterFrame();
    EXPECT_NEAR(drawn.x - previous.x, perFrame, 1e-9) << "frame " << frame;
    EXPECT_EQ(drawn.y, previous.y);
    previous = drawn;
  }
  EXPECT_EQ(group().steps() - stepsBefore, 1u) << "the physics took exactly one step of dt";
  EXPECT_EQ(mainRun().time(), group().dt());
  EXPECT_NEAR(previous.x, mainRun().positions()[0].x, 1e-12)
      << "after 20 frames the drawn ball is where the step put it";
}

TEST_F(SmoothMotion, PausedShowsTheSteppedStateExactly) {
  openCrossingBall();
  QTest::keyClick(window->sidebar()->timeScaleSlider()->slider(), Qt::Key_Home);
  for (int frame = 0; frame < 7; ++frame)
    drawnAfterFrame();
  ASSERT_GT(group().pendingTime(), 0.0);
  view()->setFocus();
  QTest::keyClick(view(), Qt::Key_Space);
  ASSERT_TRUE(runs().paused());
  EXPECT_EQ(drawnAfterFrame(), mainRun().positions()[0]);
  // A single step ('.') while paused: the step's state, nothing ahead of it.
  const std::uint64_t steps = group().steps();
  QTest::keyClick(view(), Qt::Key_Period);
  ASSERT_EQ(group().steps(), steps + 1);
  EXPECT_EQ(drawnAfterFrame(), mainRun().positions()[0]);
}

TEST_F(SmoothMotion, WhatEachFrameDrawsWhileItsStepRunsMovesEveryFrameInSlowMotion) {
  openCrossingBall();
  QTest::keyClick(window->sidebar()->timeScaleSlider()->slider(), Qt::Key_Home);
  view()->repaint();
  Vec2 previous = view()->drawnPositions(0)[0];
  const double perFrame = kVelocity.x * 0.05 * kFrame;
  // 41 frames hold two steps: in their frames the drawing happens with the step out, from the
  // state before it; were that state not carried over the step's time, the ball would jump
  // back a step's flight (2.5 mm · 20) there.
  for (int frame = 1; frame <= 41; ++frame) {
    window->advanceFrame(kFrame);
    QCoreApplication::processEvents();  // the paint a frame without a step asks for
    const Vec2 drawn = view()->drawnPositions(0)[0];
    EXPECT_NEAR(drawn.x - previous.x, perFrame, 1e-9) << "frame " << frame;
    previous = drawn;
  }
  ASSERT_EQ(group().steps(), 2u);
}

TEST_F(SmoothMotion, AFrameDrawsTheStateBeforeItsStepCarriedOverTheStepsTime) {
  // Two balls that collide head-on within the next step: what the frame draws is their flight
  // from the state before the step, not the state after the collision.
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {ball({7.68, 4.5}, {2.0, 0.0}, 0.3), ball({8.32, 4.5}, {-2.0, 0.0}, 0.3)};
  open(scene);
  const std::vector<Vec2> before(mainRun().positions().begin(), mainRun().positions().end());
  window->advanceFrame(kFrame);
  ASSERT_EQ(group().steps(), 1u);
  // Carried over the step (dt) and the time left over after it.
  const double ahead = group().dt() + group().pendingTime();
  const Vec2 drawnRight = view()->drawnPositions(0)[1];
  EXPECT_NEAR(view()->drawnPositions(0)[0].x, before[0].x + 2.0 * ahead, 1e-12);
  EXPECT_NEAR(drawnRight.x, before[1].x - 2.0 * ahead, 1e-12);
  EXPECT_GT(mainRun().velocities()[1].x, 0.0) << "the step itself did collide them";
  // The next frame draws the collided state: the right ball is on its way back.
  window->advanceFrame(kFrame);
  EXPECT_GT(view()->drawnPositions(0)[1].x, drawnRight.x);
}

TEST_F(SmoothMotion, AtFullSpeedTheBallMovesOneStepPerFrame) {
  // A step is due every frame at 1×: the drawn motion is the physics' own, v·dt per frame.
  openCrossingBall();
  Vec2 previous = drawnAfterFrame();
  for (int frame = 1; frame <= 10; ++frame) {
    const Vec2 drawn = drawnAfterFrame();
    EXPECT_NEAR(drawn.x - previous.x, kVelocity.x * kFrame, 1e-9) << "frame " << frame;
    previous = drawn;
  }
}

}  // namespace
}  // namespace fooball::gui::testing
