#pragma once

class QDockWidget;
class QMainWindow;

namespace fooball::gui {

/// How the main window's docks share it: the charts a strip under the box, the settings a
/// column beside it, the statistics a tab beside the charts.

/// Tabs `statistics` with `charts` whenever it is opened, unless the user has moved it, and
/// brings it to the front of its tabs.
void tabWithChartsWhenOpened(QMainWindow& window, QDockWidget& statistics, QDockWidget& charts);
/// Gives the charts and the settings their first share of the window (queued: after layout).
void giveDocksFirstShare(QMainWindow& window, QDockWidget& charts, QDockWidget& settings);
/// The window's height changed from `oldHeight` (px): the charts keep their share of it (queued).
void keepChartsShare(QMainWindow& window, QDockWidget& charts, int oldHeight);

}  // namespace fooball::gui
