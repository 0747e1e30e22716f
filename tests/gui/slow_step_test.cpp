// A backend step that takes seconds (Box2D with one very fast ball among hundreds: up to 1,000
// Box2D steps, each sweeping the ball through the gas) must not freeze the window: it runs in
// the background, the window shows the state before it, and pausing or changing anything gives
// it up.

#include <QComboBox>
#include <QLabel>
#include <QStatusBar>
#include <QtTest/QTest>
#include <chrono>
#include <vector>

#include "fooball/random_balls.h"
#include "gui_fixture.h"
#include "registry.h"
#include "run/step_worker.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

/// Two big balls heading for each other, one at `speed` m/s, among `count` small ones. At
/// 3.6e5 m/s one Box2D step of this scene takes ~10 s on the 2-core CI machine (measured with
/// fooball-cli run): 1,000 Box2D steps, each sweeping the fast ball through the gas.
Scene gasWithAFastBall(double speed, std::size_t count = 300) {
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {fooball::testing::ball({4.0, 4.5}, {3.0, 0.0}),
                 fooball::testing::ball({12.0, 4.5}, {-speed, 0.0})};
  RandomBalls gas;
  gas.count = count - scene.balls.size();
  gas.minRadius = 0.1;
  gas.maxRadius = 0.2;
  gas.seed = 7;
  addRandomBalls(scene, gas);
  return scene;
}
constexpr double kVeryFast = 3.6e5;  // m/s

std::vector<Vec2> copyOf(std::span<const Vec2> values) {
  return {values.begin(), values.end()};
}

/// A step given up on ends soon after (its backend honours requestStop()), so no CPU is
/// burnt on it: 5 s is hundreds of Box2D steps of this scene, against ~10 s for all of them.
bool givenUpStepsEnd() {
  return QTest::qWaitFor([] { return StepWorker::givenUpStepsRunning() == 0; }, 5000);
}

class SlowStep : public GuiTest {
 protected:
  void open(const Scene& scene, const std::string& backend,
            const std::vector<std::string>& compare = {}) {
    GuiTest::open(scene, backend, compare);
    runs().setStepPatience(RunController::kDefaultStepPatience);  // the app's
  }
  void pause() {
    for (QAction* action : window->findChildren<QAction*>()) {
      if (action->shortcut() == QKeySequence(Qt::Key_Space)) action->trigger();
    }
  }
};

TEST_F(SlowStep, RunsInTheBackgroundWhileTheWindowShowsTheStateBeforeIt) {
  open(gasWithAFastBall(kVeryFast), "box2d");
  const std::vector<Vec2> before = copyOf(mainRun().positions());
  frames(3);
  ASSERT_TRUE(runs().stepping()) << "the step must outlast the patience for this test to mean "
                                    "anything";
  EXPECT_EQ(copyOf(mainRun().positions()), before);
  EXPECT_EQ(group().time(), 0.0);
  EXPECT_GT(runs().stepSeconds(), 0.0);
  window->updateStatusBar();
  bool stepShownRunning = false;
  for (const QLabel* label : window->statusBar()->findChildren<QLabel*>())
    stepShownRunning = stepShownRunning || label->text().endsWith(QStringLiteral(" s so far"));
  EXPECT_TRUE(stepShownRunning) << "the status bar says a step is running, not its last cost";
  view()->repaint();  // drawing reads the state before the step, which nothing writes
  pause();
  EXPECT_TRUE(givenUpStepsEnd());
}

TEST_F(SlowStep, PausingGivesItUpAndKeepsTheStateShown) {
  open(gasWithAFastBall(kVeryFast), "box2d");
  const std::vector<Vec2> before = copyOf(mainRun().positions());
  frames(1);
  ASSERT_TRUE(runs().stepping());
  pause();
  EXPECT_TRUE(runs().paused());
  EXPECT_FALSE(runs().stepping());
  EXPECT_EQ(copyOf(mainRun().positions()), before);
  EXPECT_EQ(group().time(), 0.0);
  EXPECT_EQ(runs().label(0), QStringLiteral("box2d"));
  EXPECT_TRUE(givenUpStepsEnd());

  // The run goes on from there, on a fresh Box2D world: slow the ball down and it steps at once.
  BallDef fast = group().ball(1);
  fast.velocity = {-3.0, 0.0};
  runs().setBall(1, fast);
  runs().setStepPatience(
      RunController::kWaitForEveryStep);  // a step of the slowed scene, however loaded
  runs().stepOnce();
  EXPECT_FALSE(runs().stepping());
  EXPECT_EQ(group().time(), kFrame);
}

TEST_F(SlowStep, SwitchingBackendGivesItUpAndContinuesFromTheStateShown) {
  open(gasWithAFastBall(kVeryFast), "box2d");
  const std::vector<Vec2> before = copyOf(mainRun().positions());
  frames(1);
  ASSERT_TRUE(runs().stepping());
  QComboBox* backends = window->sidebar()->runList()->backendBox(0);
  backends->setCurrentIndex(backends->findText(QStringLiteral("elastic")));
  emit backends->activated(backends->currentIndex());
  EXPECT_EQ(runs().label(0), QStringLiteral("elastic"));
  EXPECT_FALSE(runs().stepping());
  EXPECT_EQ(copyOf(mainRun().positions()), before);
  EXPECT_TRUE(givenUpStepsEnd());
  runs().setStepPatience(
      RunController::kWaitForEveryStep);  // elastic steps on from there, however loaded
  frames(1);
  EXPECT_EQ(group().time(), kFrame);
}

TEST_F(SlowStep, InCompareModeBothRunsWaitForTheSlowOneAndAreGivenUpTogether) {
  open(gasWithAFastBall(kVeryFast), "box2d", {"elastic"});
  // Box2D holds the start in float, elastic in double: each run's own start state.
  const std::vector<Vec2> start0 = copyOf(runs().run(0).positions());
  const std::vector<Vec2> start1 = copyOf(runs().run(1).positions());
  frames(2);
  ASSERT_TRUE(runs().stepping());
  EXPECT_EQ(runs().run(1).time(), 0.0) << "lockstep: elastic waits";
  pause();
  EXPECT_FALSE(runs().stepping());
  EXPECT_EQ(runs().run(0).time(), 0.0);
  EXPECT_EQ(runs().run(1).time(), 0.0);
  EXPECT_EQ(copyOf(runs().run(0).positions()), start0);
  EXPECT_EQ(copyOf(runs().run(1).positions()), start1);
  EXPECT_TRUE(givenUpStepsEnd());
}

TEST_F(SlowStep, AStepThatFinishesInTheBackgroundLandsAsIfItHadBeenWaitedFor) {
  // A smaller scene whose step takes around a second: collected by a later frame, it must be
  // the very step the driver would have taken in place (Box2D is deterministic).
  const Scene scene = gasWithAFastBall(kVeryFast / 10.0, 100);
  Simulation reference(scene, createBackend("box2d"));
  reference.step();

  open(scene, "box2d");
  runs().setStepPatience(std::chrono::milliseconds(0));  // whatever this machine's speed
  frames(1);
  ASSERT_TRUE(runs().stepping());
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        frames(1);
        return !runs().stepping();
      },
      60'000));
  EXPECT_EQ(runs().run(0).steps(), 1u);
  EXPECT_EQ(copyOf(mainRun().positions()), copyOf(reference.positions()));
  EXPECT_EQ(copyOf(mainRun().velocities()), copyOf(reference.velocities()));
}

}  // namespace
}  // namespace fooball::gui::testing
