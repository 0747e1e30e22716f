#include "window/dock_layout.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace fooball::gui {

namespace {

constexpr int kSidebarWidth = 300;  // px

/// The charts' first height: a quarter of the window's, and 30 px more from a window 900 px tall
/// on, where that gives one row of charts its full height (title, legend, plot, time axis)
/// without scrolling. At 16:9 the box stays the largest thing on screen from 1000×650 to
/// 3840×2160, in compare mode too (layout_test.cpp).
int firstChartsHeight(int windowHeight) {
  constexpr double kShare = 0.25;
  constexpr int kExtra = 30;  // px
  return int(kShare * windowHeight) + std::clamp(windowHeight - 650, 0, 250) * kExtra / 250;
}

}  // namespace

void tabWithChartsWhenOpened(QMainWindow& window, QDockWidget& statistics, QDockWidget& charts) {
  // Tabbed when opened, not before: a saved layout with a tab group holding a closed dock comes
  // back wider than the window's least width (868 px against 505 on an 800 px test screen).
  QObject::connect(statistics.toggleViewAction(), &QAction::toggled, &window,
                   [&window, &statistics, &charts](bool open) {
                     if (!open) return;
                     if (window.dockWidgetArea(&statistics) == Qt::BottomDockWidgetArea &&
                         !statistics.isFloating() && !charts.isHidden() &&
                         !window.tabifiedDockWidgets(&statistics).contains(&charts)) {
                       window.tabifyDockWidget(&charts, &statistics);
                     }
                     // To the front of its tabs once the layout has run: before, a dock just
                     // shown or in a window not shown yet has no tab to raise.
                     QTimer::singleShot(0, &statistics, &QDockWidget::raise);
                   });
}

void giveDocksFirstShare(QMainWindow& window, QDockWidget& charts, QDockWidget& settings) {
  // Once the window has its size: the view gets most of it, the charts a strip below (they
  // scroll when there are more than fit), the settings a column.
  QMetaObject::invokeMethod(
      &window,
      [&window, &charts, &settings] {
        window.resizeDocks({&charts}, {firstChartsHeight(window.height())}, Qt::Vertical);
        window.resizeDocks({&settings}, {kSidebarWidth}, Qt::Horizontal);
      },
      Qt::QueuedConnection);
}

void keepChartsShare(QMainWindow& window, QDockWidget& charts, int oldHeight) {
  // The dock keeps its height in pixels when the window changes, so shrinking a tall window
  // would leave the box a sliver above the charts: keep the charts' share of the height instead
  // (the share the user dragged them to, or the first one).
  if (oldHeight == window.height() || charts.isHidden() || charts.isFloating()) return;
  const double share = double(charts.height()) / double(oldHeight);
  QMetaObject::invokeMethod(
      &window,
      [&window, &charts, share] {
        window.resizeDocks({&charts}, {int(std::lround(share * window.height()))}, Qt::Vertical);
      },
      Qt::QueuedConnection);
}

}  // namespace fooball::gui
