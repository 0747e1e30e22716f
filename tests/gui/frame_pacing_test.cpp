// Frames when the physics is dear. The status bar's cost of a step is the step's own run on its
// worker, not the drawing the window does meanwhile. And a frame takes no more steps than a
// frame's time of stepping holds at the last step's cost: a machine that cannot keep up takes
// one step a frame, and so shows several times the frames at the same simulation speed.

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <limits>

#include "fooball/random_balls.h"
#include "gui_fixture.h"

namespace fooball::gui::testing {
namespace {

class FramePacing : public GuiTest {};

TEST_F(FramePacing, TheStepCostShownIsTheStepsOwnNotTheDrawingBesideIt) {
  // Three still balls: a step is microseconds, drawing the window's view a good part of a
  // millisecond, and each frame draws while its step runs. The least of several frames, so that
  // a worker descheduled once on a busy machine does not decide.
  open(stillBalls());
  double leastStepMs = std::numeric_limits<double>::infinity();
  double leastDrawMs = std::numeric_limits<double>::infinity();
  for (int frame = 0; frame < 9; ++frame) {
    window->advanceFrame(kFrame);
    leastStepMs = std::min(leastStepMs, runs().stepTiming(0).millisecondsPerStep);
    QElapsedTimer draw;
    draw.start();
    view()->repaint();
    leastDrawMs = std::min(leastDrawMs, double(draw.nsecsElapsed()) * 1e-6);
  }
  EXPECT_GT(leastStepMs, 0.0);
  EXPECT_LT(leastStepMs, 0.5 * leastDrawMs)
      << "the step's cost must not include the drawing done while it ran";
  EXPECT_DOUBLE_EQ(runs().lastStepSeconds(), runs().stepTiming(0).millisecondsPerStep * 1e-3);
}

TEST_F(FramePacing, AFrameTakesNoMoreStepsThanAFrameOfSteppingHolds) {
  // 20,000 balls at 40 substeps: a step costs tens of milliseconds here, more than a frame, so
  // a frame that falls 0.1 s behind (6 steps due) takes one step, not the time-scale cap of 4.
  Scene scene = fooball::testing::emptyBox();
  RandomBalls gas;
  gas.count = 20'000;
  gas.minRadius = gas.maxRadius = 0.02;
  addRandomBalls(scene, gas);
  open(scene, "elastic:substeps=40");
  frames(2);
  const double cost = runs().lastStepSeconds();  // s
  ASSERT_GT(cost, 0.0);
  const double affordable = std::floor(RunGroup::kSteppingPerFrame / cost);
  const auto expected = static_cast<std::uint64_t>(
      std::clamp(affordable, 1.0, RunGroup::kMaxStepsPerFramePerTimeScale));
  const std::uint64_t before = group().steps();
  window->advanceFrame(6 * kFrame);
  EXPECT_EQ(group().steps() - before, expected) << "at " << cost * 1e3 << " ms a step";
  EXPECT_LT(expected, 4u) << "the scene must be dear enough for the step cost to bind";
}

}  // namespace
}  // namespace fooball::gui::testing
