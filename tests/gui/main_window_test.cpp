#include <QAction>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>

#include "charts/chart_panel.h"
#include "fooball/version.h"
#include "frames/frame_loop.h"
#include "gui_fixture.h"
#include "registry.h"
#include "view/simulation_view.h"
#include "widgets/view_text.h"
#include "window/window_settings.h"

namespace fooball::gui::testing {
namespace {

/// Each test reads and writes a settings file of its own (test mode keeps them out of the user's
/// config): CTest runs tests in parallel processes, which would otherwise share one file.
class MainWindowTest : public GuiTest {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    QCoreApplication::setApplicationName(applicationName_ + QLatin1Char('-') +
                                         QString::fromLatin1(test->name()) + QLatin1Char('-') +
                                         QString::number(QCoreApplication::applicationPid()));
    QSettings().clear();
  }
  void TearDown() override {
    QSettings().clear();
    QCoreApplication::setApplicationName(applicationName_);
  }

 private:
  QString applicationName_ = QCoreApplication::applicationName();
};

TEST_F(MainWindowTest, LiveUpdatesRunTheSimulationInRealTime) {
  open(stillBalls());
  window->startLiveUpdates();
  QTest::qWait(300);
  EXPECT_GT(mainRun().time(), 0.0);
  EXPECT_LT(mainRun().time(), 1.0) << "never ahead of the wall clock";
}

TEST_F(MainWindowTest, SettingsAreRememberedBetweenRunsOutsideTheUsersConfig) {
  ASSERT_TRUE(QStandardPaths::isTestModeEnabled());
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
}

/// A window that reads and writes the (test-mode) settings, as an interactive start does.
StartupOptions rememberingOptions() {
  StartupOptions options;
  options.scene = stillBalls();
  options.runs = {RunSpec{"elastic", {}}};
  options.rememberSettings = true;
  return options;
}

/// Closes a remembering window after `arrange` has had its way with it: what it leaves in the
/// settings is what the next start reads.
template <typename Arrange>
void closeAfter(Arrange arrange) {
  MainWindow first(rememberingOptions());
  first.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&first));
  arrange(first);
  first.close();
}

void expectFullyOn(const QRect& available, const QWidget& window) {
  EXPECT_TRUE(available.contains(window.frameGeometry()))
      << "window " << window.frameGeometry().x() << "," << window.frameGeometry().y() << " "
      << window.frameGeometry().width() << "x" << window.frameGeometry().height()
      << " is not inside the screen's " << available.width() << "x" << available.height();
}

TEST_F(MainWindowTest, ARememberedWindowOffTheScreenStartsFullyOnIt) {
  const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
  closeAfter([&](MainWindow& previous) {
    // Above and beyond the screen, and larger than it, as after a monitor was unplugged.
    previous.resize(available.width() + 400, available.height() + 300);
    previous.move(available.right() + 500, available.top() - 400);
  });
  MainWindow second(rememberingOptions());
  expectFullyOn(available, second);
  second.show();
  QCoreApplication::processEvents();  // the second fit, once the frame is known
  expectFullyOn(available, second);
}

TEST_F(MainWindowTest, AStatisticsDockClosedLastTimeOpensAsATabOfTheCharts) {
  // Closed all along, or opened and closed: either way a tab of the charts when opened again.
  for (const bool openedLastTime : {false, true}) {
    QSettings().clear();
    closeAfter([openedLastTime](MainWindow& previous) {
      if (!openedLastTime) return;
      previous.statisticsDock()->toggleViewAction()->trigger();
      QCoreApplication::processEvents();
      previous.statisticsDock()->toggleViewAction()->trigger();
    });
    MainWindow second(rememberingOptions());
    second.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&second));
    EXPECT_TRUE(second.statisticsDock()->isHidden());
    second.statisticsDock()->toggleViewAction()->trigger();
    QCoreApplication::processEvents();
    EXPECT_TRUE(second.tabifiedDockWidgets(second.statisticsDock()).contains(second.chartsDock()))
        << "not beside the charts, squeezing them; opened last time: " << openedLastTime;
    EXPECT_TRUE(second.charts()->mapTo(&second, QPoint()).y() < 0)
        << "in front of the charts' tab; opened last time: " << openedLastTime;
  }
}

TEST_F(MainWindowTest, AFirstStartFitsTheDefaultSizeToASmallScreen) {
  const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
  ASSERT_LT(available.width(), 1440) << "the offscreen screen is smaller than the default size";
  MainWindow started(rememberingOptions());
  EXPECT_EQ(started.size(), available.size()) << "as large as fits, before it has a frame";
  started.show();
  QCoreApplication::processEvents();
  expectFullyOn(available, started);
}

TEST_F(MainWindowTest, SettingsOfAnotherVersionKeepTheirValuesButNotTheirLayout) {
  // 0: a file from before settings had versions; kSettingsVersion + 1: a newer app's.
  for (const int version : {0, kSettingsVersion + 1}) {
    QSettings().clear();
    closeAfter([](MainWindow& previous) {
      previous.chartsDock()->hide();
      previous.view()->setTemperatureColouring(true);
    });
    if (version == 0) {
      QSettings().remove("settings/version");
    } else {
      QSettings().setValue("settings/version", version);
    }
    MainWindow second(rememberingOptions());
    second.show();
    EXPECT_TRUE(second.chartsDock()->isVisible()) << "another version's dock layout was applied";
    EXPECT_TRUE(second.view()->temperatureColouring()) << "its plain values are still read";
  }
}

TEST_F(MainWindowTest, TheSameVersionRestoresTheDockLayout) {
  closeAfter([](MainWindow& previous) { previous.chartsDock()->hide(); });
  MainWindow second(rememberingOptions());
  second.show();
  EXPECT_FALSE(second.chartsDock()->isVisible());
}

TEST_F(MainWindowTest, DamagedNumbersInTheSettingsFallBackToTheDefaults) {
  QSettings settings;
  settings.setValue("settings/version", kSettingsVersion);
  settings.setValue("time/scale", "nan");
  settings.setValue("mouse/strength", "a lot");
  settings.setValue("mouse/mode", 1000);
  MainWindow started(rememberingOptions());
  EXPECT_EQ(started.frames().timeScale(), FrameLoop::kDefaultTimeScale);
  EXPECT_EQ(started.runs().group().interactions().strength, Interactions::kDefaultStrength);
  EXPECT_EQ(started.runs().group().interactions().mode, MouseMode::Slingshot) << "clamped";
}

QAction* menuAction(const QMainWindow& window, const QString& menuText, const QString& text) {
  for (QAction* menu : window.menuBar()->actions()) {
    if (menu->text() != menuText || !menu->menu()) continue;
    for (QAction* action : menu->menu()->actions()) {
      if (action->text() == text) return action;
    }
  }
  return nullptr;
}

TEST_F(MainWindowTest, ResetLayoutBringsBackHiddenAndFloatingDocks) {
  open(stillBalls());
  window->chartsDock()->hide();
  window->sidebarDock()->setFloating(true);
  window->resize(500, 400);
  QAction* reset = menuAction(*window, QStringLiteral("&View"), QStringLiteral("Reset &layout"));
  ASSERT_NE(reset, nullptr);
  reset->trigger();
  QCoreApplication::processEvents();
  EXPECT_TRUE(window->chartsDock()->isVisible());
  EXPECT_FALSE(window->sidebarDock()->isFloating());
  EXPECT_EQ(window->dockWidgetArea(window->sidebarDock()), Qt::RightDockWidgetArea);
  EXPECT_EQ(window->dockWidgetArea(window->chartsDock()), Qt::RightDockWidgetArea);
  expectFullyOn(QGuiApplication::primaryScreen()->availableGeometry(), *window);
  EXPECT_GT(window->view()->width() * window->view()->height(),
            window->chartsDock()->width() * window->chartsDock()->height())
      << "the box is the largest thing again";
}

/// The text of the message box `action` opens (read, then closed, from inside its event loop).
QString messageBoxText(QAction& action) {
  QString shown;
  QTimer::singleShot(0, [&] {
    for (QWidget* widget : QApplication::topLevelWidgets()) {
      if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
        shown = box->text();
        box->accept();
      }
    }
  });
  action.trigger();  // modal: returns once the timer has read and closed the box
  return shown;
}

TEST_F(MainWindowTest, AboutShowsTheVersion) {
  open(stillBalls());
  QAction* about = menuAction(*window, QStringLiteral("&Help"), QStringLiteral("&About FooBall"));
  ASSERT_NE(about, nullptr);
  const QString shown = messageBoxText(*about);
  EXPECT_TRUE(shown.contains(QStringLiteral("FooBall ") + fromView(kVersion)))
      << shown.toStdString();
}

TEST_F(MainWindowTest, HelpExplainsTheChartsTheBaselineAndEveryMethod) {
  open(stillBalls());
  QAction* help =
      menuAction(*window, QStringLiteral("&Help"), QStringLiteral("&Reading the charts"));
  ASSERT_NE(help, nullptr);
  const QString shown = messageBoxText(*help);
  for (const char* topic : {"residual", "method's own error", "chaos baseline", "Divergence"})
    EXPECT_TRUE(shown.contains(QString::fromUtf8(topic))) << topic;
  for (const BackendInfo& backend : registeredBackends())
    EXPECT_TRUE(shown.contains(QStringLiteral("<b>%1</b>").arg(fromView(backend.name))))
        << backend.name;
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
