// The box first: at every window size from 1000×650 to 3840×2160, single run and compare mode
// (overlay and side by side), the box's widget is larger than either dock and, in one box
// (single run, overlay), so is the box of balls itself; the window fits 1000×650, the
// sidebar's contents fit it, and the docks come back with View → Reset layout. The statistics
// dock, opened, takes the charts' place and keeps the same rule.

#include <QDockWidget>
#include <QScrollArea>
#include <QSpinBox>

#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

const std::vector<QSize> kSizes{{1000, 650}, {1440, 900}, {2560, 1440}, {3840, 2160}};

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
};

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
};

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
    window->resize(size);
    settle();
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
  EXPECT_EQ(window->dockWidgetArea(window->chartsDock()), Qt::BottomDockWidgetArea);
  EXPECT_EQ(window->dockWidgetArea(window->sidebarDock()), Qt::RightDockWidgetArea);
  // The first share again (the window itself is fitted to the test's small offscreen screen).
  EXPECT_GE(window->chartsDock()->height(), 0.24 * window->height());
  EXPECT_LE(window->chartsDock()->height(), 0.30 * window->height());
  EXPECT_EQ(window->chartsDock()->width(), window->width()) << "the full width under the box";
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
