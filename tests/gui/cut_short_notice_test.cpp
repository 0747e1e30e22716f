// A run whose steps are cut short at a work cap the user set says so in the status bar, naming
// the run; an exact run with no cap (the default) never shows it.

#include <QLabel>
#include <QStatusBar>

#include "fooball/presets.h"
#include "gui_fixture.h"

namespace fooball::gui::testing {
namespace {

class CutShortNotice : public GuiTest {
 protected:
  const QLabel* notice() const {
    return window->statusBar()->findChild<QLabel*>(QStringLiteral("cutShortNotice"));
  }
};

TEST_F(CutShortNotice, NamesTheRunWhoseStepsWereCutShort) {
  // Rain settling into a pile: thousands of events a step, more than a cap of 1 per ball (500
  // a step) allows, but none loops at one instant (CliTest.StepsCutShortAtAnEventCap…).
  open(loadPreset("rain"), "exact", {"exact:max_events_per_ball=1"});
  window->updateStatusBar();
  ASSERT_NE(notice(), nullptr);
  EXPECT_TRUE(notice()->isHidden()) << "nothing has been stepped yet";
  frames(120);
  ASSERT_GT(runs().run(1).counters().cutShortSteps, 0u);
  window->updateStatusBar();
  EXPECT_FALSE(notice()->isHidden());
  // Compare mode names runs by number; the tooltip has the run's spec.
  EXPECT_EQ(notice()->text(), QStringLiteral("⚠ steps cut short: run 1"));
  EXPECT_TRUE(notice()->toolTip().contains(
      QStringLiteral("exact:max_events_per_ball=1: %1 steps were cut short")
          .arg(runs().run(1).counters().cutShortSteps)))
      << notice()->toolTip().toStdString();
  EXPECT_EQ(runs().run(0).counters().cutShortSteps, 0u) << "the uncapped run is exact";
}

}  // namespace
}  // namespace fooball::gui::testing
