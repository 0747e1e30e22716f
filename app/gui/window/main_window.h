#pragma once

#include <QMainWindow>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "fooball/run_spec.h"
#include "fooball/scene.h"

class QDockWidget;
class QScrollArea;
class QUndoStack;

namespace fooball::gui {

class ChartPanel;
class CompareReadout;
class FrameLoop;
class RunController;
class RunFeed;
class SettingsSidebar;
class SimulationView;
class StatisticsPanel;
class StatusPanel;
class TimelineBar;
class WindowActions;

/// What the window starts on; main() fills it from the command line and remembered settings.
struct StartupOptions {
  Scene scene;
  QString presetName;  ///< the preset the scene came from; empty for a scene file
  QString sourceName;  ///< shown in the title: the preset's or the file's name
  /// Run 0 first, then the compare runs (--backend, --compare): 1 to RunGroup::kMaxRuns.
  std::vector<RunSpec> runs;
  /// Ball count right after loading, as if set with the spinner (--balls).
  std::optional<std::size_t> balls;
  /// Drawing options to turn on (CommandLine::show) and attractors to place (m).
  QStringList show;
  std::vector<Vec2> attractors;
  /// Read and write QSettings (window layout, drawing, mouse and speed settings). Off for
  /// --frames runs and tests, which must neither depend on nor change the user's settings.
  bool rememberSettings = true;
};

/// The FooBall window: it creates the simulation view with the compare readout above it, the
/// settings sidebar, the chart panel and the gas statistics in docks, the menus (WindowActions),
/// the status bar (StatusPanel) and the frame loop (FrameLoop), connects them to the RunController,
/// and keeps the widgets in step with the runs. The runs' bookkeeping lives in the engine's
/// RunGroup; what the sidebar's controls do is in sidebar_wiring.cpp, scene files and presets
/// in scene_commands.cpp.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// Throws std::invalid_argument for a bad run spec, SceneError when `balls` do not fit.
  explicit MainWindow(const StartupOptions& options, QWidget* parent = nullptr);
  ~MainWindow() override;

  RunController& runs() const { return *runs_; }
  SimulationView* view() const { return view_; }
  SettingsSidebar* sidebar() const { return sidebar_; }
  ChartPanel* charts() const { return charts_; }
  CompareReadout* compareReadout() const { return compareReadout_; }
  StatisticsPanel* statistics() const { return statistics_; }
  WindowActions& actions() const { return *actions_; }
  FrameLoop& frames() const { return *frames_; }
  /// The runs' state into the charts, readouts, counters, statistics and change markers.
  RunFeed& feed() const { return *feed_; }
  StatusPanel& status() const { return *status_; }
  TimelineBar& timeline() const { return *timeline_; }
  QDockWidget* sidebarDock() const { return sidebarDock_; }
  /// Edits and deletes of balls (ball_commands.h). Its commands name balls by index and hold
  /// their states, so whatever renumbers or replaces the balls clears it: loading a scene or
  /// preset, Restart, Reset scene and a ball-count change.
  QUndoStack* undoStack() const { return undoStack_; }
  QDockWidget* chartsDock() const { return chartsDock_; }
  /// Closed at first; opened, it shares the charts' place as a tab.
  QDockWidget* statisticsDock() const { return statisticsDock_; }
  /// The preset the scene came from; empty for a scene file.
  const QString& presetName() const { return presetName_; }
  /// The preset's or the scene file's name, as in the title.
  const QString& sourceName() const { return sourceName_; }

  /// How errors reach the user: a message box by default; tests record them instead.
  using ErrorReporter = std::function<void(const QString& title, const QString& message)>;
  void setErrorReporter(ErrorReporter reporter) { reportError_ = std::move(reporter); }
  void reportError(const QString& title, const QString& message) { reportError_(title, message); }

  /// Every run starts on `scene` (valid); the sidebar, the charts and the title follow.
  void loadScene(const Scene& scene, const QString& presetName, const QString& sourceName);
  /// Back to the loaded scene at t = 0, keeping the settings of now.
  void restart();
  /// View → Reset layout: the settings and charts back in place and shown, the statistics
  /// closed, the default window size (fitted to the screen), the charts and settings at their
  /// first share.
  void resetLayout();
  /// The loaded scene exactly as loaded, sliders at their defaults.
  void resetScene();

  /// One frame (FrameLoop::advance): physics for `elapsedSeconds` of real time (times the
  /// speed slider), the charts' samples and a repaint request.
  void advanceFrame(double elapsedSeconds);
  /// Real-time frames from a timer (the interactive app; --frames drives advanceFrame itself).
  void startLiveUpdates();
  void updateStatusBar();

  void showStatus(const QString& message);
  /// Brings every control in line with the runs (after a load or reset).
  void syncSidebar();
  /// The run list, the readout and the title after runs changed.
  void showRuns();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void createDocks();
  /// The settings dock's least width: its widest control row, beside the scroll bar.
  void fitSidebarWidth();
  /// Gives the charts and the settings their first share of the window (queued: after layout).
  void sizeDocks();
  void connectRuns();
  void resetCharts();
  void updateTitle();

  std::unique_ptr<RunController> runs_;
  bool rememberSettings_;
  QString presetName_;
  QString sourceName_;
  bool docksSized_ = false;   ///< the docks got their first size (or a remembered layout)
  bool shownOnce_ = false;    ///< shown before: the frame fit (keepFullyOnScreen) is done
  QByteArray defaultLayout_;  ///< saveState() of the docks as created, for View → Reset layout

  SimulationView* view_ = nullptr;
  CompareReadout* compareReadout_ = nullptr;
  SettingsSidebar* sidebar_ = nullptr;
  ChartPanel* charts_ = nullptr;
  QDockWidget* sidebarDock_ = nullptr;
  QScrollArea* sidebarScroll_ = nullptr;
  QDockWidget* chartsDock_ = nullptr;
  StatisticsPanel* statistics_ = nullptr;
  QDockWidget* statisticsDock_ = nullptr;
  WindowActions* actions_ = nullptr;
  StatusPanel* status_ = nullptr;
  TimelineBar* timeline_ = nullptr;
  std::unique_ptr<RunFeed> feed_;
  FrameLoop* frames_ = nullptr;
  QUndoStack* undoStack_ = nullptr;

  ErrorReporter reportError_;
};

}  // namespace fooball::gui
