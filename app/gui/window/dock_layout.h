#pragma once

class QDockWidget;
class QMainWindow;

namespace fooball::gui {

/// How the main window's docks share it: the settings a column beside the box, the charts a
/// column of their own beside them on a wide window or a tab in front of them on a narrow one,
/// the statistics a tab beside the charts.

/// Tabs `statistics` with `charts` whenever it is opened, unless the user has moved it, and
/// brings it to the front of its tabs.
void tabWithChartsWhenOpened(QMainWindow& window, QDockWidget& statistics, QDockWidget& charts);
/// Gives the charts and the settings their first place and share of the window (queued: after
/// layout).
void giveDocksFirstShare(QMainWindow& window, QDockWidget& charts, QDockWidget& settings);
/// The window's width changed: the charts take their own column or join the settings' as it
/// crosses the width where they fit beside the box, unless the user has moved a dock (queued).
void followWindowWidth(QMainWindow& window, QDockWidget& charts, QDockWidget& settings);

}  // namespace fooball::gui
