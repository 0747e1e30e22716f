#include "window/dock_layout.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QTimer>

namespace fooball::gui {

namespace {

constexpr int kSidebarWidth = 300;  // px
/// px of window width from which the charts get a column of their own beside the box; below,
/// they share the settings' column as a tab. A chart readable at 160 px of plot needs about
/// 270 px of height with its title, legend and time axis: under the box, at 1000×650 (and at
/// 1440×900 with eight runs' compare table above the box) it left the box a strip.
constexpr int kChartsBesideFrom = 1300;
/// The charts column's share of the window's width: the box keeps the larger part of what the
/// settings leave (layout_test.cpp).
constexpr double kChartsShare = 0.25;

int firstChartsWidth(int windowWidth) {
  return int(kChartsShare * windowWidth);
}

/// The settings and the charts are where they start: open (a tab behind another is open too),
/// docked in the right dock area.
bool inTheirPlaces(const QMainWindow& window, QDockWidget& charts, QDockWidget& settings) {
  const auto placed = [&window](QDockWidget& dock) {
    return dock.toggleViewAction()->isChecked() && !dock.isFloating() &&
           window.dockWidgetArea(&dock) == Qt::RightDockWidgetArea;
  };
  return placed(charts) && placed(settings);
}

/// Beside the box from kChartsBesideFrom px of width, with the tabs they share (the statistics);
/// below it, they and those tabs join the settings' column as tabs, the charts in front (or the
/// statistics, if they were the tab shown).
void placeCharts(QMainWindow& window, QDockWidget& charts, QDockWidget& settings, bool sized) {
  const bool tabbed = window.tabifiedDockWidgets(&charts).contains(&settings);
  const bool beside = window.width() >= kChartsBesideFrom;
  if (beside) {
    if (tabbed) {
      // Out of the group and back as a column right of the charts' (splitDockWidget() would
      // only add it to the group again).
      window.removeDockWidget(&settings);
      window.addDockWidget(Qt::RightDockWidgetArea, &settings, Qt::Horizontal);
      settings.show();
    }
    window.resizeDocks({&charts, &settings}, {firstChartsWidth(window.width()), kSidebarWidth},
                       Qt::Horizontal);
  } else {
    if (!tabbed) {
      QDockWidget* front = &charts;
      const QList<QDockWidget*> sharing = window.tabifiedDockWidgets(&charts);
      for (QDockWidget* dock : sharing) {
        if (!dock->visibleRegion().isEmpty()) front = dock;
      }
      window.tabifyDockWidget(&settings, &charts);
      for (QDockWidget* dock : sharing)
        window.tabifyDockWidget(&charts, dock);
      front->raise();
    } else if (!sized) {
      charts.raise();
    }
    // Both: resizeDocks() passes over a tab that is not shown, and either may be in front.
    window.resizeDocks({&charts, &settings}, {kSidebarWidth, kSidebarWidth}, Qt::Horizontal);
  }
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
  // Once the window has its size: the view gets most of it, the charts and the settings a
  // column each, or the charts in front of the settings in one.
  // After the layout requests already posted (a restored state's): resizeDocks() on docks not
  // laid out yet leaves them at the width they had floating.
  QTimer::singleShot(
      0, &window, [&window, &charts, &settings] { placeCharts(window, charts, settings, false); });
}

void followWindowWidth(QMainWindow& window, QDockWidget& charts, QDockWidget& settings) {
  // Only while the docks are where they start: a dock the user moved stays where it is.
  QMetaObject::invokeMethod(
      &window,
      [&window, &charts, &settings] {
        if (inTheirPlaces(window, charts, settings)) placeCharts(window, charts, settings, true);
      },
      Qt::QueuedConnection);
}

}  // namespace fooball::gui
