#pragma once

#include <QMainWindow>
#include <memory>
#include <optional>
#include <vector>

#include "fooball/run_spec.h"
#include "fooball/scene.h"
#include "recording/recording_frame_source.h"
#include "window/window_settings.h"

class QDockWidget;
class QScrollArea;

namespace fooball::gui {

class BallCommands;
class CompareReadout;
class RunFeed;
class SceneCommands;
class SceneSession;
class SettingsSidebar;
class StatisticsPanel;
class StatusPanel;
class TimelineBar;
class UserMessages;
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
/// the status bar (StatusPanel) and the frame loop (FrameLoop), connects them to the
/// RunController and to each other, and restores the remembered settings. What a load or reset
/// does is SceneSession's; what the sidebar's controls do, SidebarController's; the mouse on the
/// box, MouseTools'; the menus, WindowActions'.
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
  SceneSession& session() const { return *session_; }
  SceneCommands& scenes() const { return *scenes_; }
  UserMessages& messages() const { return *messages_; }
  QDockWidget* sidebarDock() const { return sidebarDock_; }
  QDockWidget* chartsDock() const { return chartsDock_; }
  /// Closed at first; opened, it shares the charts' place as a tab.
  QDockWidget* statisticsDock() const { return statisticsDock_; }
  /// What a recording draws and drives (File → Record…, --record).
  RecordingTarget recordingTarget() const;

  /// View → Reset layout: the settings and charts back in place and shown, the statistics
  /// closed, the default window size (fitted to the screen), the charts and settings at their
  /// first share.
  void resetLayout();
  /// One frame (FrameLoop::advance): physics for `elapsedSeconds` of real time (times the
  /// speed slider), the charts' samples and a repaint request.
  void advanceFrame(double elapsedSeconds);
  /// Real-time frames from a timer (the interactive app; --frames drives advanceFrame itself).
  void startLiveUpdates();
  void updateStatusBar();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void createDocks();
  /// The window follows the runs, the scene and the menus: title, status bar, layout.
  void connectParts();
  void updateTitle();
  RememberedParts remembered();

  std::unique_ptr<RunController> runs_;
  bool rememberSettings_;
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
  UserMessages* messages_ = nullptr;
  SceneSession* session_ = nullptr;
  std::unique_ptr<SceneCommands> scenes_;
  std::unique_ptr<BallCommands> balls_;
};

}  // namespace fooball::gui
