#include <QAction>
#include <QSettings>
#include <QStandardPaths>

#include "gui_fixture.h"
#include "simulation_view.h"

namespace fooball::gui::testing {
namespace {

class MainWindowTest : public GuiTest {};

TEST_F(MainWindowTest, LiveUpdatesRunTheSimulationInRealTime) {
  open(stillBalls());
  window->startLiveUpdates();
  QTest::qWait(300);
  EXPECT_GT(mainRun().time(), 0.0);
  EXPECT_LT(mainRun().time(), 1.0) << "never ahead of the wall clock";
}

TEST_F(MainWindowTest, SettingsAreRememberedBetweenRunsOutsideTheUsersConfig) {
  ASSERT_TRUE(QStandardPaths::isTestModeEnabled());
  QSettings().clear();
  StartupOptions options;
  options.scene = stillBalls();
  options.runs = {RunSpec{"elastic", {}}};
  {
    MainWindow first(options);
    first.show();
    first.view()->setTemperatureColouring(true);
    first.runs().changeTools([](RunGroup& group) { group.setMouseMode(MouseMode::Slingshot); });
    first.close();
  }
  MainWindow second(options);
  EXPECT_TRUE(second.view()->temperatureColouring());
  EXPECT_EQ(second.runs().group().interactions().mode, MouseMode::Slingshot);
  QSettings().clear();
}

TEST_F(MainWindowTest, SpaceShortcutPausesAndContinues) {
  open(stillBalls());
  QAction* pause = nullptr;
  for (QAction* action : window->findChildren<QAction*>()) {
    if (action->shortcut() == QKeySequence(Qt::Key_Space)) pause = action;
  }
  ASSERT_NE(pause, nullptr);
  pause->trigger();
  EXPECT_TRUE(runs().paused());
  pause->trigger();
  EXPECT_FALSE(runs().paused());
}

}  // namespace
}  // namespace fooball::gui::testing
