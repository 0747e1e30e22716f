#pragma once

#include <QElapsedTimer>
#include <QMainWindow>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "fooball/scene.h"
#include "frame_rate.h"

class QAction;
class QDockWidget;
class QLabel;
class QScrollArea;
class QTimer;

namespace fooball::gui {

class BenchmarkDialog;
class ChartPanel;
class CompareReadout;
class RunController;
class SettingsSidebar;
class SimulationView;

/// What the window starts on; main() fills it from the command line and remembered settings.
struct StartupOptions {
  Scene scene;
  QString presetName;  ///< the preset the scene came from; empty for a scene file
  QString sourceName;  ///< shown in the title: the preset's or the file's name
  QString backend;     ///< the main run's backend
  QString compare;     ///< empty: no compare run
  /// Ball count right after loading, as if set with the spinner (--balls).
  std::optional<std::size_t> balls;
  /// Drawing options to turn on (CommandLine::show) and attractors to place (m).
  QStringList show;
  std::vector<Vec2> attractors;
  /// Read and write QSettings (window layout, drawing, mouse and speed settings). Off for
  /// --frames runs and tests, which must neither depend on nor change the user's settings.
  bool rememberSettings = true;
};

/// The FooBall window: the simulation view with the compare readout above it, the settings
/// sidebar and the chart panel in docks, a status bar, menus. It wires the widgets to the
/// RunController and drives the frames.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// Throws std::invalid_argument for an unknown backend, SceneError when `balls` do not fit.
  explicit MainWindow(const StartupOptions& options, QWidget* parent = nullptr);
  ~MainWindow() override;

  RunController& runs() const { return *runs_; }
  SimulationView* view() const { return view_; }
  SettingsSidebar* sidebar() const { return sidebar_; }
  ChartPanel* charts() const { return charts_; }
  CompareReadout* compareReadout() const { return compareReadout_; }
  QAction* benchmarkAction() const { return benchmarkAction_; }
  /// Tools → Benchmark's dialog; none until first opened.
  BenchmarkDialog* benchmarkDialog() const { return benchmark_; }

  /// How errors reach the user: a message box by default; tests record them instead.
  using ErrorReporter = std::function<void(const QString& title, const QString& message)>;
  void setErrorReporter(ErrorReporter reporter) { reportError_ = std::move(reporter); }

  /// Loads a scene file into every run; on error shows it and keeps the current scene.
  bool openSceneFile(const QString& path);
  bool saveSceneFile(const QString& path);
  /// Starts on a preset; on error shows it and keeps the current scene.
  bool openPreset(const QString& name);
  /// Sets the ball count like the spinner; on error shows it in the status bar and keeps the
  /// balls.
  bool setBallCount(std::size_t count);

  /// One frame: physics for `elapsedSeconds` of real time (times the speed slider), the
  /// charts' samples and a repaint request. The live timer and --frames both come here.
  void advanceFrame(double elapsedSeconds);
  /// Feeds every run's metrics to the charts now.
  void sampleCharts();
  /// Real-time frames from a timer (the interactive app; --frames drives advanceFrame itself).
  void startLiveUpdates();
  void updateStatusBar();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void createDocks();
  void createActions();
  void createMenus();
  void createStatusBar();
  void connectSidebar();
  void connectView();
  void connectRuns();

  void loadScene(const Scene& scene, const QString& presetName, const QString& sourceName);
  void resetCharts();
  void syncSidebar();
  void showSelectedBall();
  void applyGravity(double magnitude);
  void setTimeScale(double timeScale);
  void chooseBackend(const QString& name);
  void chooseCompare(const QString& name);
  void resetSliders();
  void resetScene();
  void markChange(const QString& label);
  void showStatus(const QString& message);
  void updateTitle();

  void openSceneDialog();
  void saveSceneDialog();
  void exportChartsPng();
  void exportChartsCsv();
  void openBenchmark();

  void readSettings();
  void writeSettings() const;

  std::unique_ptr<RunController> runs_;
  bool rememberSettings_;
  QString presetName_;
  QString sourceName_;
  double timeScale_ = 1.0;
  bool docksSized_ = false;  ///< the docks got their first size (or a remembered layout)

  SimulationView* view_ = nullptr;
  CompareReadout* compareReadout_ = nullptr;
  SettingsSidebar* sidebar_ = nullptr;
  ChartPanel* charts_ = nullptr;
  QDockWidget* sidebarDock_ = nullptr;
  QScrollArea* sidebarScroll_ = nullptr;
  QDockWidget* chartsDock_ = nullptr;

  QAction* pauseAction_ = nullptr;
  QAction* stepAction_ = nullptr;
  QAction* temperatureAction_ = nullptr;
  QAction* tethersAction_ = nullptr;
  QAction* velocityVectorsAction_ = nullptr;
  QAction* centreOfMassAction_ = nullptr;
  QAction* overlayAction_ = nullptr;
  QAction* sideBySideAction_ = nullptr;
  QAction* benchmarkAction_ = nullptr;

  BenchmarkDialog* benchmark_ = nullptr;
  bool pausedForBenchmark_ = false;  ///< the benchmark paused the runs and continues them

  QLabel* cursorStatus_ = nullptr;
  QLabel* backendStatus_ = nullptr;
  QLabel* ballsStatus_ = nullptr;
  QLabel* timeStatus_ = nullptr;
  QLabel* stepsStatus_ = nullptr;
  QLabel* framesStatus_ = nullptr;
  QLabel* stepCostStatus_ = nullptr;

  QTimer* frameTimer_ = nullptr;
  QTimer* statusTimer_ = nullptr;
  QElapsedTimer frameClock_;
  FrameRate frameRate_;
  int framesSinceSample_ = 0;
  int framesSinceReadout_ = 0;

  ErrorReporter reportError_;
};

}  // namespace fooball::gui
