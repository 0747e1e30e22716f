// A seeded monkey: thousands of random user actions on the main window (mouse tools in every
// mode and scope, attractors, sliders to any position, ball counts from 0 up, backends,
// compare mode, pause and step, presets, walls and collisions, ball edits, resets), with the
// window's invariants checked after every batch. FOOBALL_MONKEY_SEED and FOOBALL_MONKEY_ACTIONS
// replay a failure or run a longer soak.

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolButton>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "backend_profiles.h"
#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "control/scene_commands.h"
#include "gui_fixture.h"
#include "robustness/case_run.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/log_slider.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

bool sanitized() {
  return qEnvironmentVariableIsSet("FOOBALL_SANITIZED");
}

std::uint64_t environmentNumber(const char* name, std::uint64_t fallback) {
  bool ok = false;
  const qulonglong value = qEnvironmentVariable(name).toULongLong(&ok);
  return ok ? value : fallback;
}

/// 3000 actions take 13–17 s in a Release build, most of it Box2D with up to 1000 balls. The
/// sanitizers slow the physics about tenfold: 300 balls at most, and 2000 actions take about 9 s.
/// FOOBALL_MONKEY_ACTIONS soaks longer (this seed meets a minute-long Box2D step at action 4000).
const std::uint64_t kDefaultSeed = 20261122;
const std::uint64_t kDefaultActions = sanitized() ? 2000 : 3000;
const int kMaxBalls = sanitized() ? 300 : 1000;
constexpr int kActionsPerBatch = 25;
constexpr int kMaxMonkeyRuns = 3;
/// The same actions with every step left to run in the background: fewer, as most steps are
/// given up and the window's work, not the physics, is what they test.
const std::uint64_t kBackgroundActions = sanitized() ? 500 : 1000;
/// The inspector's values are typed from ±40 (m, m/s, kg): off the box (refused), overlapping,
/// fast. Not the fields' far ends (±10⁶ m/s): one ball that fast among a few hundred makes
/// Box2D's continuous collision take minutes per step (docs/accuracy.md), and GuiTest waits for
/// every step.
constexpr double kMaxTyped = 40.0;

class GuiMonkey : public GuiTest {
 protected:
  void SetUp() override {
    open(fooball::testing::emptyBox());
    window->scenes().openPreset(QStringLiteral("default"));
    sidebar_ = window->sidebar();
    for (QAction* action : window->findChildren<QAction*>()) {
      if (action->shortcut() == QKeySequence(Qt::Key_Space)) pause_ = action;
      if (action->shortcut() == QKeySequence(Qt::Key_Period)) step_ = action;
    }
    for (QPushButton* button : sidebar_->findChildren<QPushButton*>()) {
      const QString text = button->text();
      if (text == QStringLiteral("Restart") || text == QStringLiteral("Reset scene") ||
          text == QStringLiteral("Reset sliders") || text.startsWith(QStringLiteral("Clear")))
        resets_.push_back(button);
    }
    ASSERT_NE(pause_, nullptr);
    ASSERT_NE(step_, nullptr);
    ASSERT_EQ(resets_.size(), 4u) << "Restart, Reset scene, Reset sliders, Clear attractors";
  }

  int uniform(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng_); }
  double uniformReal(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(rng_);
  }
  bool chance(double p) { return uniformReal(0.0, 1.0) < p; }
  QPoint anywhereInView() {
    return {uniform(0, view()->width() - 1), uniform(0, view()->height() - 1)};
  }
  template <class Widget>
  Widget* named(const char* name) const {
    return window->findChild<Widget*>(QString::fromLatin1(name));
  }
  /// As a user picking item `index` from the list: the sidebar acts on activated(), which
  /// setCurrentIndex() alone does not emit.
  static void choose(QComboBox* box, int index) {
    box->setCurrentIndex(index);
    emit box->activated(index);
  }
  void clickRadio(const char* name) {
    if (auto* radio = named<QRadioButton>(name)) radio->click();
  }

  /// One random action; returns its name for the failure message.
  std::string act() {
    switch (uniform(0, 12)) {
      case 0:
      case 1: {  // a press, a drag over a few frames, a release, in a random mode and scope
        const char* modes[] = {"attractRadio", "repelRadio", "grabRadio", "slingshotRadio"};
        const char* scopes[] = {"allRadio", "nearestRadio", "selectedRadio"};
        const char* mode = modes[uniform(0, 3)];
        const char* scope = scopes[uniform(0, 2)];
        clickRadio(mode);
        clickRadio(scope);
        QTest::mousePress(view(), Qt::LeftButton, {}, anywhereInView());
        for (int move = uniform(0, 3); move > 0; --move) {
          QTest::mouseMove(view(), anywhereInView());
          frames(1);
        }
        QTest::mouseRelease(view(), Qt::LeftButton, {}, anywhereInView());
        return std::string("drag ") + mode + " " + scope;
      }
      case 2:
        QTest::mouseClick(view(), Qt::RightButton, {}, anywhereInView());
        return "attractor";
      case 3: {  // a slider to a random position, an end half the time
        LogSlider* sliders[] = {sidebar_->gravitySlider(), sidebar_->airResistanceSlider(),
                                sidebar_->strengthSlider(), sidebar_->timeScaleSlider()};
        QSlider* slider = sliders[uniform(0, 3)]->slider();
        const int position = chance(0.5) ? (chance(0.5) ? slider->minimum() : slider->maximum())
                                         : uniform(slider->minimum(), slider->maximum());
        slider->setValue(position);
        return "slider " + slider->parentWidget()->objectName().toStdString() + " to " +
               std::to_string(position);
      }
      case 4: {
        const int choices[] = {0, 1, uniform(0, kMaxBalls / 10), uniform(0, kMaxBalls), kMaxBalls};
        const int count = choices[uniform(0, 4)];
        sidebar_->ballCountBox()->setValue(count);
        return "balls " + std::to_string(count);
      }
      case 5: {
        QComboBox* box = sidebar_->runList()->backendBox(0);
        const int index = uniform(0, box->count() - 1);
        if (mustNotWaitFor(box->itemText(index)))
          return "backend: skipped " + box->itemText(index).toStdString();
        choose(box, index);
        return "backend " + box->currentText().toStdString();
      }
      case 6: {  // add a run, remove one, switch a run's backend or the chaos baseline
        RunListEditor* list = sidebar_->runList();
        const int run = uniform(0, list->rowCount() - 1);
        // Up to three runs: more than two exercises N-way compare, and every run more costs
        // another whole simulation per step. The monkey waits for every step, so a compare run
        // is never of a backend whose step can take minutes (its profile says so); run 0 is not
        // switched to one either while the monkey waits for every step (mustNotWaitFor).
        if (chance(0.3) && list->rowCount() < kMaxMonkeyRuns) {
          QComboBox* backends = list->newRunBackendBox();
          choose(backends, uniform(0, backends->count() - 1));
          if (fooball::testing::profileFor(backends->currentText().toStdString())
                  .stepsCanTakeMinutes)
            return "add run: skipped " + backends->currentText().toStdString();
          list->addButton()->click();
          return "add run " + backends->currentText().toStdString();
        }
        if (chance(0.3) && list->removeButton(run)->isVisible()) {
          list->removeButton(run)->click();
          return "remove run " + std::to_string(run);
        }
        if (chance(0.3)) {
          list->baselineBox()->click();
          return "baseline " + std::to_string(list->baselineBox()->isChecked());
        }
        QComboBox* box = list->backendBox(run);
        const int index = uniform(0, box->count() - 1);
        if (mustNotWaitFor(box->itemText(index)))
          return "run " + std::to_string(run) + " backend: skipped " +
                 box->itemText(index).toStdString();
        choose(box, index);
        return "run " + std::to_string(run) + " backend " + box->currentText().toStdString();
      }
      case 7:
        if (chance(0.5) && step_->isEnabled()) {
          step_->trigger();
          return "single step";
        }
        pause_->trigger();
        return "pause/continue";
      case 8: {
        auto* presets = named<QComboBox>("presetBox");
        choose(presets, uniform(0, presets->count() - 1));
        ballsMayBeOutside_ = false;
        return "preset " + presets->currentText().toStdString();
      }
      case 9: {
        static const char* const kBoxes[] = {"ballCollisionsBox", "leftWallBox", "rightWallBox",
                                             "bottomWallBox", "topWallBox"};
        auto* box = named<QCheckBox>(kBoxes[uniform(0, 4)]);
        box->click();
        return box->objectName().toStdString() + (box->isChecked() ? " on" : " off");
      }
      case 10:
        return editABall();
      case 11: {
        QPushButton* button = resets_[static_cast<std::size_t>(uniform(0, 3))];
        button->click();
        if (button->text() == QStringLiteral("Restart") ||
            button->text() == QStringLiteral("Reset scene"))
          ballsMayBeOutside_ = false;
        return button->text().toStdString();
      }
      default:
        frames(uniform(1, 5));
        return "frames";
    }
  }

  /// Pauses, clicks a ball, and types a random (possibly refused) value into a field of the
  /// inspector, or deletes the ball.
  std::string editABall() {
    if (mainRun().ballCount() == 0) return "edit: no balls";
    if (!runs().paused()) pause_->trigger();
    const auto index = static_cast<std::size_t>(uniform(0, int(mainRun().ballCount()) - 1));
    QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf(mainRun().positions()[index]));
    if (!group().selected()) return "edit: ball hidden under another";
    if (chance(0.1)) {
      named<QPushButton>("inspectorDelete")->click();
      return "delete ball";
    }
    const char* fields[] = {"inspectorX",  "inspectorY",      "inspectorVx",
                            "inspectorVy", "inspectorRadius", "inspectorMass"};
    const char* name = fields[uniform(0, 5)];
    auto* field = named<QDoubleSpinBox>(name);
    field->setFocus();
    field->setValue(
        uniformReal(std::max(field->minimum(), -kMaxTyped), std::min(field->maximum(), kMaxTyped)));
    QTest::keyClick(field, Qt::Key_Return);
    return std::string("edit ") + name;
  }

  /// Whether the monkey must not switch a run to `backend`: one step of it can take minutes in
  /// states the monkey reaches (its profile says so) and this monkey waits for every step. Which
  /// states a seed reaches depends on every random choice before, and so on how many backends
  /// are registered: a seed that avoided Box2D's minute-long steps with three backends met one
  /// with four (dense preset, 1000 balls, a strong attractor, run 0 switched to box2d). The
  /// monkey that leaves every step to the background (stepPatience_ 0) switches run 0 to any
  /// backend, so each one still meets every action there.
  bool mustNotWaitFor(const QString& backend) const {
    return stepPatience_ == RunController::kWaitForEveryStep &&
           fooball::testing::profileFor(backend.toStdString()).stepsCanTakeMinutes;
  }

  bool closed() const {
    const Walls walls = group().world().walls;
    return walls.left && walls.right && walls.bottom && walls.top;
  }

  /// Every run's state is finite, inside a closed box, and counted as the UI says; the status
  /// bar and the charts follow the runs.
  void checkInvariants() {
    for (int run = 0; run < runs().runCount(); ++run) {
      const Simulation& simulation = runs().run(run);
      ASSERT_EQ(simulation.ballCount(), group().ballCount()) << "run " << run;
      // A centre may lie beyond a wall by the backend's documented slack: none for the
      // double-precision methods, Box2D's continuous-collision tolerance for box2d
      // (tests/robustness/case_run.cpp derives it).
      const double slack =
          robustness::tolerancesFor(group().spec(std::size_t(run)).backend).wallSlack;
      const Box box = simulation.box();
      for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
        const Vec2 p = simulation.positions()[i];
        const Vec2 v = simulation.velocities()[i];
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(v.x) &&
                    std::isfinite(v.y))
            << group().spec(std::size_t(run)).backend << " ball " << i;
        if (!closed() || ballsMayBeOutside_) continue;
        ASSERT_TRUE(p.x >= -slack && p.x <= box.width + slack && p.y >= -slack &&
                    p.y <= box.height + slack)
            << group().spec(std::size_t(run)).backend << " ball " << i << " at (" << p.x << ", "
            << p.y << ") outside the " << box.width << " × " << box.height << " m box";
      }
    }
    EXPECT_EQ(sidebar_->ballCountBox()->value(), static_cast<int>(group().ballCount()));

    // Running again, the clock, the status bar and the charts move on, every step waited for.
    // Pausing gives the step in flight up; a single step taken while paused is out with the
    // runs paused, so they continue first (a continue alone would leave it out, and a frame
    // does not wait for a step that is already out).
    if (runs().stepping()) {
      if (runs().paused()) pause_->trigger();
      pause_->trigger();
    }
    if (runs().paused()) pause_->trigger();
    runs().setStepPatience(RunController::kWaitForEveryStep);
    // Enough frames that step for a new chart sample (one every 3); at the slowest speed
    // (0.05×) a frame is a fraction of a step, so up to 300 frames.
    const double before = group().time();
    int steppingFrames = 0;
    for (int frame = 0; frame < 300 && steppingFrames < 4; ++frame) {
      const double frameStart = group().time();
      frames(1);
      if (group().time() > frameStart) ++steppingFrames;
    }
    ASSERT_GT(group().time(), before)
        << (runs().paused() ? "paused" : "running") << (runs().stepping() ? ", a step out" : "")
        << "; errors shown: " << errors.join(QStringLiteral(" | ")).toStdString();
    window->updateStatusBar();
    const QString shown =
        QObject::tr("%L1 balls, t = %2 s").arg(group().ballCount()).arg(group().time(), 0, 'f', 2);
    bool ballsAndTimeShown = false;
    for (const QLabel* label : window->statusBar()->findChildren<QLabel*>())
      ballsAndTimeShown = ballsAndTimeShown || label->text() == shown;
    EXPECT_TRUE(ballsAndTimeShown) << shown.toStdString();
    runs().setStepPatience(stepPatience_);
    window->charts()->refresh();
    for (int run = 0; run < runs().runCount(); ++run) {
      EXPECT_GT(storedSampleCount(*window->charts(), run), 0u);
      EXPECT_GT(displayedPointCount(*window->charts(), ChartPanel::kEnergyChart, run), 0)
          << "E_kin " << runs().run(run).metrics().sums.kineticEnergy << " E_pot "
          << runs().run(run).metrics().sums.potentialEnergy;
    }
  }

  SettingsSidebar* sidebar_ = nullptr;
  QAction* pause_ = nullptr;
  QAction* step_ = nullptr;
  std::vector<QPushButton*> resets_;
  /// Walls were off since the balls were last put in the box (a scene loaded or restarted):
  /// balls that left then stay out when the walls come back, as the walls only reflect.
  bool ballsMayBeOutside_ = false;
  std::mt19937_64 rng_;
  std::chrono::milliseconds stepPatience_ = RunController::kWaitForEveryStep;

  void runActions(std::uint64_t defaultActions) {
    const std::uint64_t seed = environmentNumber("FOOBALL_MONKEY_SEED", kDefaultSeed);
    const std::uint64_t actions = environmentNumber("FOOBALL_MONKEY_ACTIONS", defaultActions);
    rng_.seed(seed);
    runs().setStepPatience(stepPatience_);
    for (std::uint64_t done = 0; done < actions;) {
      std::ostringstream batch;
      batch << "FOOBALL_MONKEY_SEED=" << seed << ", actions " << done << "…:";
      for (int i = 0; i < kActionsPerBatch && done < actions; ++i, ++done) {
        batch << ' ' << act() << ';';
        if (!closed()) ballsMayBeOutside_ = true;
        frames(uniform(0, 2));
      }
      SCOPED_TRACE(batch.str());
      checkInvariants();
      if (HasFatalFailure() || HasNonfatalFailure()) return;
    }
  }
};

TEST_F(GuiMonkey, RandomActionsKeepTheWindowConsistent) {
  runActions(kDefaultActions);
}

TEST_F(GuiMonkey, RandomActionsGiveUpStepsRunningInTheBackground) {
  // No patience: every step is left to run in the background, so most actions meet one in
  // flight and give it up (slow_step_test.cpp) or find it finished. Which steps land depends on
  // the machine's timing, so a seed does not replay exactly; the invariants hold either way.
  stepPatience_ = std::chrono::milliseconds(0);
  runActions(kBackgroundActions);
}

}  // namespace
}  // namespace fooball::gui::testing
