// The box first: at every window size from 1000×650 to 3840×2160, single run and compare mode
// (overlay and side by side), the box's widget is larger than either dock and, in one box
// (single run, overlay), so is the box of balls itself; the window fits 1000×650, the
// sidebar's contents fit it, and the docks come back with View → Reset layout. The statistics
// dock, opened, takes the charts' place and keeps the same rule. Every chart on screen is whole
// and readable (a plot of 160 px at least, its title and time axis) at 1000×650, 1440×900 and
// 2560×1440, with one run and eight, overlay and side by side, with and without the statistics;
// Reset layout brings back the first-start layout exactly.

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QFontMetricsF>
#include <QScrollArea>
#include <QSpinBox>

#include "charts/chart_panel.h"
#include "charts/time_chart.h"
#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

const std::vector<QSize> kSizes{{1000, 650}, {1440, 900}, {2560, 1440}, {3840, 2160}};

/// Seven runs beside run 0's elastic: eight, the most a run group holds (no hosted engines: no
/// Node.js child needed).
const std::vector<std::string> kSevenMore{
    "exact", "box2d", "chipmunk", "xpbd", "bullet", "elastic:substeps=4", "box2d:substeps=8"};

struct Mode {
  const char* name;
  std::vector<std::string> compare;
  bool sideBySide;
};
const std::vector<Mode> kModes{
    {"single run", {}, false},
    {"overlay of 3", {"exact", "box2d"}, false},
    {"side by side, 3", {"exact", "box2d"}, true},
    {"overlay of 5", {"exact", "box2d", "chipmunk", "xpbd"}, false},
    {"overlay of 8", kSevenMore, false},
    {"side by side, 8", kSevenMore, true},
};
/// The modes the charts' geometry is read in: one run and eight, overlay and side by side.
const std::vector<Mode> kChartModes{kModes[0], kModes[4], kModes[5]};
/// The sizes it is read at.
const std::vector<QSize> kChartSizes{{1000, 650}, {1440, 900}, {2560, 1440}};
/// px of plot area a chart needs at least to be read: five value ticks 32 px apart.
constexpr double kReadablePlotHeight = 160.0;

int area(const QRect& rect) {
  return rect.width() * rect.height();
}

/// All the balls' boxes together (side by side: every tile's).
int boxArea(const MainWindow& window) {
  int total = 0;
  const int tiles =
      window.view()->compareLayout() == CompareLayout::SideBySide ? window.runs().runCount() : 1;
  for (int run = 0; run < tiles; ++run)
    total += area(window.view()->transformForRun(run).boxRect());
  return total;
}

class Layout : public GuiTest {
 protected:
  /// A window as a new user sees it at `size`: the docks at their first share.
  void openAt(QSize size, const Mode& mode) {
    StartupOptions options;
    options.scene = stillBalls();
    options.sourceName = QStringLiteral("test");
    options.runs = {parseRunSpec("elastic")};
    for (const std::string& spec : mode.compare)
      options.runs.push_back(parseRunSpec(spec));
    options.rememberSettings = false;
    window = std::make_unique<MainWindow>(options);
    if (mode.sideBySide) window->view()->setCompareLayout(CompareLayout::SideBySide);
    window->resize(size);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    settle();
  }

  /// Resizes the window as dragging its edge does: a window narrower than the charts' column
  /// beside the box allows stops at that width, the charts join the settings' column, and the
  /// drag goes on.
  void dragTo(QSize size) {
    for (int i = 0; i < 2; ++i) {
      window->resize(size);
      settle();
    }
  }

  /// The queued dock sizing and the layouts after it.
  static void settle() {
    for (int i = 0; i < 5; ++i)
      QCoreApplication::processEvents();
  }

  void expectBoxLargest(const std::string& where) const {
    // Side by side, tiles of the box's shape leave gutters in a view of another shape: there the
    // view (every tile and its label) is what must be largest.
    const bool oneBox =
        window->view()->compareLayout() == CompareLayout::Overlay || window->runs().runCount() == 1;
    const int box = boxArea(*window);
    const int view = area(window->view()->rect());
    for (const QDockWidget* dock :
         {window->sidebarDock(), window->chartsDock(), window->statisticsDock()}) {
      if (dock->isHidden()) continue;
      const std::string against = " against the " + dock->objectName().toStdString() + " (" +
                                  std::to_string(dock->width()) + "×" +
                                  std::to_string(dock->height()) + ")";
      EXPECT_GT(view, area(dock->geometry())) << where << ": the view (" << window->view()->width()
                                              << "×" << window->view()->height() << ")" << against;
      if (oneBox) {
        EXPECT_GT(box, area(dock->geometry()))
            << where << ": the box (" << window->view()->transformForRun(0).boxRect().width() << "×"
            << window->view()->transformForRun(0).boxRect().height() << ")" << against;
      }
    }
  }

  /// Every chart on screen (the time charts, the statistics' histogram) is whole, has a plot
  /// area of at least kReadablePlotHeight and shows its title and its x axis' labels and title.
  /// There is at least one.
  void expectChartsReadable(const std::string& where) const {
    int onScreen = 0;
    for (QChartView* view : window->findChildren<QChartView*>()) {
      // The viewport covers the view: the view's own visible region is empty.
      if (!view->isVisible() || view->viewport()->visibleRegion().isEmpty()) continue;
      ++onScreen;
      const QChart* chart = view->chart();
      const std::string which = where + ", chart '" + chart->title().toStdString() + "'";
      EXPECT_GE(chart->plotArea().height(), kReadablePlotHeight)
          << which << ": plot " << chart->plotArea().width() << "×" << chart->plotArea().height()
          << " in a view of " << view->width() << "×" << view->height();
      EXPECT_EQ(view->viewport()->visibleRegion().boundingRect(), view->viewport()->rect())
          << which << ": cut off";
      // The statistics' histogram is named by its dock's tab.
      if (dynamic_cast<const TimeChart*>(view) != nullptr) {
        EXPECT_FALSE(chart->title().isEmpty()) << which;
      }
      const QList<QAbstractAxis*> xAxes = chart->axes(Qt::Horizontal);
      ASSERT_FALSE(xAxes.isEmpty()) << which;
      for (const QAbstractAxis* axis : xAxes) {
        EXPECT_TRUE(axis->isVisible() && axis->labelsVisible()) << which << ": x axis' labels";
        EXPECT_TRUE(axis->isTitleVisible() && !axis->titleText().isEmpty())
            << which << ": x axis' title";
      }
      // Room under the plot for the labels and the title, which Qt otherwise elides.
      const double below = view->height() - chart->plotArea().bottom();
      const double needed = QFontMetricsF(xAxes.front()->labelsFont()).height() +
                            QFontMetricsF(xAxes.front()->titleFont()).height();
      EXPECT_GE(below, needed) << which << ": the x axis cut";
    }
    EXPECT_GE(onScreen, 1) << where << ": no chart on screen";
  }
};

TEST_F(Layout, EveryChartOnScreenIsReadableAtEverySizeAndMode) {
  // Before: at 1000×650 a strip of each plot without its time axis; side by side with eight runs
  // no plot at all; at 1440×900 with eight runs plots about 60 px tall.
  for (const Mode& mode : kChartModes) {
    for (const QSize size : kChartSizes) {
      for (const bool statistics : {false, true}) {
        openAt(size, mode);
        if (statistics) {
          window->actions().applyShowOptions({QStringLiteral("statistics")});
          settle();
        }
        const std::string where = std::string(mode.name) + " at " + std::to_string(size.width()) +
                                  "×" + std::to_string(size.height()) +
                                  (statistics ? ", statistics open" : "");
        // The whole size: eight runs' compare table scrolls sideways rather than holding the
        // window wider (1,176 px before).
        EXPECT_EQ(window->size(), size) << where;
        expectChartsReadable(where);
        QDockWidget* shown = statistics ? window->statisticsDock() : window->chartsDock();
        EXPECT_FALSE(shown->visibleRegion().isEmpty()) << where << ": the dock just opened shown";
        // The settings are on screen, or a tab beside the charts.
        EXPECT_TRUE(!window->sidebarDock()->visibleRegion().isEmpty() ||
                    window->tabifiedDockWidgets(window->sidebarDock()).contains(shown))
            << where << ": the settings reachable";
      }
    }
  }
}

TEST_F(Layout, TheChartSelectorBringsEachChartOnScreenWhenNotAllFit) {
  // 1000×650 with eight runs: one whole chart fits; the selector names the four.
  openAt(kChartSizes[0], kChartModes[1]);
  auto* selector = window->charts()->findChild<QComboBox*>(QStringLiteral("chartSelector"));
  ASSERT_NE(selector, nullptr);
  ASSERT_TRUE(selector->isVisible());
  ASSERT_EQ(selector->count(), 4);
  for (int chart = 0; chart < selector->count(); ++chart) {
    selector->setCurrentIndex(chart);
    settle();
    std::vector<QString> onScreen;
    for (const QChartView* view : window->charts()->findChildren<QChartView*>()) {
      if (view->isVisible() && !view->viewport()->visibleRegion().isEmpty())
        onScreen.push_back(view->chart()->title());
    }
    ASSERT_FALSE(onScreen.empty()) << selector->currentText().toStdString();
    // The chart chosen leads (titles start with the selector's name: "Energy budget residual"
    // for "Residual" is named by its first word too).
    const QString first = onScreen.front();
    const QString name = selector->currentText();
    EXPECT_TRUE(first.startsWith(name) || (name == QStringLiteral("Residual") &&
                                           first.startsWith(QStringLiteral("Energy budget"))))
        << name.toStdString() << " chosen, " << first.toStdString() << " shown";
    expectChartsReadable("selector at " + name.toStdString());
  }
}

TEST_F(Layout, ChartsStayReadableAsTheWindowIsResized) {
  openAt(kChartSizes.back(), kChartModes[0]);
  for (const QSize size : {kChartSizes[0], kChartSizes[1], kChartSizes[2], kChartSizes[0]}) {
    dragTo(size);
    const std::string where =
        "resized to " + std::to_string(size.width()) + "×" + std::to_string(size.height());
    EXPECT_EQ(window->size(), size) << where;
    expectChartsReadable(where);
  }
}

TEST_F(Layout, ResetLayoutRestoresTheFirstStartLayoutExactly) {
  // Before: after a small window the x axis' title stayed cut at 1440×900, reset or not.
  for (const Mode& mode : kChartModes) {
    // The first start: a new window at the size Reset layout gives (1440×900 fitted to the
    // test's screen).
    openAt({1440, 900}, mode);
    window->resetLayout();
    settle();
    const QSize firstSize = window->size();
    openAt(firstSize, mode);
    const QByteArray firstState = window->saveState();
    const QRect firstCharts = window->chartsDock()->geometry();
    const QRect firstSettings = window->sidebarDock()->geometry();
    window->resize(1000, 650);
    settle();
    window->sidebarDock()->hide();
    window->actions().applyShowOptions({QStringLiteral("statistics")});
    window->chartsDock()->setFloating(true);
    settle();
    window->resetLayout();
    settle();
    EXPECT_EQ(window->size(), firstSize) << mode.name;
    EXPECT_EQ(window->chartsDock()->geometry(), firstCharts) << mode.name;
    EXPECT_EQ(window->sidebarDock()->geometry(), firstSettings) << mode.name;
    EXPECT_TRUE(window->statisticsDock()->isHidden()) << mode.name;
    EXPECT_EQ(window->saveState(), firstState) << mode.name;
  }
}

TEST_F(Layout, BoxIsTheLargestThingAtEverySizeAndMode) {
  for (const Mode& mode : kModes) {
    for (const QSize size : kSizes) {
      openAt(size, mode);
      const std::string where = std::string(mode.name) + " at " + std::to_string(size.width()) +
                                "×" + std::to_string(size.height());
      EXPECT_EQ(window->size(), size) << where;
      expectBoxLargest(where);
    }
  }
}

TEST_F(Layout, BoxIsTheLargestThingWithTheStatisticsOpen) {
  for (const Mode& mode : kModes) {
    for (const QSize size : kSizes) {
      openAt(size, mode);
      window->actions().applyShowOptions({QStringLiteral("statistics")});
      settle();
      const std::string where = std::string(mode.name) + " with statistics at " +
                                std::to_string(size.width()) + "×" + std::to_string(size.height());
      ASSERT_FALSE(window->statisticsDock()->isHidden()) << where;
      EXPECT_EQ(window->size(), size) << where;
      expectBoxLargest(where);
    }
  }
}

TEST_F(Layout, BoxStaysLargestWhenTheWindowIsResized) {
  // From the largest to the smallest and back: the docks keep their share, not their pixels.
  openAt(kSizes.back(), kModes[1]);
  for (const QSize size : {kSizes[0], kSizes[2], kSizes[1], kSizes[3], kSizes[0]}) {
    dragTo(size);
    expectBoxLargest("resized to " + std::to_string(size.width()) + "×" +
                     std::to_string(size.height()));
  }
}

TEST_F(Layout, WindowFits1000x650InEveryMode) {
  for (const Mode& mode : kModes) {
    openAt({1000, 650}, mode);
    const QSize minimum = window->minimumSizeHint().expandedTo(window->minimumSize());
    EXPECT_LE(minimum.width(), 1000) << mode.name;
    EXPECT_LE(minimum.height(), 650) << mode.name;
    EXPECT_EQ(window->size(), QSize(1000, 650)) << mode.name;
  }
}

TEST_F(Layout, SidebarContentsFitItsColumnAt1000x650) {
  // The counters' last column and the runs' remove buttons were cut off at 1000 px.
  for (const Mode& mode : kModes) {
    openAt({1000, 650}, mode);
    auto* scroll = qobject_cast<QScrollArea*>(window->sidebarDock()->widget());
    ASSERT_NE(scroll, nullptr);
    const QWidget* contents = scroll->widget();
    EXPECT_LE(contents->minimumSizeHint().width(), scroll->viewport()->width()) << mode.name;
    EXPECT_LE(contents->width(), scroll->viewport()->width()) << mode.name;
  }
}

TEST_F(Layout, ResetLayoutBringsBackDocksMovedHiddenAndFloated) {
  openAt({1440, 900}, kModes[0]);
  window->sidebarDock()->hide();
  window->chartsDock()->setFloating(true);
  window->resetLayout();
  settle();
  EXPECT_FALSE(window->sidebarDock()->isHidden());
  EXPECT_FALSE(window->chartsDock()->isFloating());
  EXPECT_EQ(window->dockWidgetArea(window->chartsDock()), Qt::RightDockWidgetArea);
  EXPECT_EQ(window->dockWidgetArea(window->sidebarDock()), Qt::RightDockWidgetArea);
  EXPECT_LE(window->sidebarDock()->width(), 320);
}

TEST_F(Layout, EscapeGivesTheKeyboardBackToTheBoxFromASidebarField) {
  openAt({1440, 900}, kModes[0]);
  QApplication::setActiveWindow(window.get());
  auto* field = window->sidebar()->findChild<QSpinBox*>();
  ASSERT_NE(field, nullptr);
  field->setFocus();
  ASSERT_TRUE(field->hasFocus());
  QTest::keyClick(field, Qt::Key_Escape);
  EXPECT_TRUE(window->view()->hasFocus());
}

}  // namespace
}  // namespace fooball::gui::testing
