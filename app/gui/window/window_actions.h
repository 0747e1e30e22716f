#pragma once

#include <QObject>
#include <QStringList>

#include "recording/recording_frame_source.h"

class QAction;
class QDockWidget;
class QMainWindow;
class QUndoStack;

namespace fooball::gui {

class BallCommands;
class BenchmarkDialog;
class FailureMapDialog;
class RecordDialog;
class RunFeed;
class SceneCommands;
class SceneSession;
class SettingsSidebar;
class ToolDialog;
class TradeoffDialog;
class UserMessages;

/// The window's menus and the actions in them: File (scenes, chart export), Simulation (pause,
/// single step, restart, resets), View (docks, drawing options, compare layout), Tools
/// (Benchmark) and Help. The drawing actions and the sidebar's check boxes mirror each other, as
/// do the compare layout's actions and the run list's choice.
class WindowActions : public QObject {
  Q_OBJECT

 public:
  /// What the actions act on; `window` gets the menus and is the dialogs' parent.
  struct Parts {
    QMainWindow& window;
    RunController& runs;
    SimulationView& view;
    SettingsSidebar& sidebar;
    ChartPanel& charts;
    RunFeed& feed;
    SceneSession& session;
    SceneCommands& scenes;
    BallCommands& balls;
    QUndoStack& undoStack;
    UserMessages& messages;
    QDockWidget& sidebarDock;
    QDockWidget& chartsDock;
    QDockWidget& statisticsDock;
    RecordingTarget recording;
  };

  explicit WindowActions(Parts parts);

  QAction* pause() const { return pause_; }
  QAction* step() const { return step_; }
  QAction* stepBack() const { return stepBack_; }
  QAction* deleteBall() const { return deleteBall_; }
  QAction* undo() const { return undo_; }
  QAction* redo() const { return redo_; }
  QAction* temperature() const { return temperature_; }
  QAction* tethers() const { return tethers_; }
  QAction* velocityVectors() const { return velocityVectors_; }
  QAction* centreOfMass() const { return centreOfMass_; }
  /// View → What to look for: the preset's caption above the box (its close button unchecks it).
  QAction* lookFor() const { return lookFor_; }
  QAction* overlay() const { return overlay_; }
  QAction* sideBySide() const { return sideBySide_; }
  QAction* benchmark() const { return benchmark_; }
  /// Tools → Benchmark's dialog; none until first opened.
  BenchmarkDialog* benchmarkDialog() const { return benchmarkDialog_; }
  QAction* tradeoff() const { return tradeoff_; }
  /// Tools → Speed vs accuracy's dialog; none until first opened.
  TradeoffDialog* tradeoffDialog() const { return tradeoffDialog_; }
  QAction* failureMap() const { return failureMap_; }
  /// File → Record…: its dialog; none until first opened.
  QAction* record() const { return record_; }
  RecordDialog* recordDialog() const { return recordDialog_; }
  /// File → Record…: shows the dialog (made on first use).
  RecordDialog* openRecord();
  /// Tools → Failure map's dialog; none until first opened.
  FailureMapDialog* failureMapDialog() const { return failureMapDialog_; }

  /// Turns on the drawing options --show names ("temperature", "vectors", "centre-of-mass",
  /// "side-by-side") and opens the docks it names ("statistics").
  void applyShowOptions(const QStringList& show);
  void showPaused(bool paused);
  /// Cancels the Tools' runs and closes their dialogs, and stops a recording (the app quits
  /// with its main window).
  void closeTools();
  /// Deletes the Tools' dialogs, which stop and join their threads (before the window's
  /// widgets go).
  void destroyTools();
  /// File → Export charts as PNG to `path`, under a caption naming the scene and the runs; says
  /// how it went in the status bar or an error.
  bool exportChartsPngTo(const QString& path);
  /// File → Save image of the box to `path`: the simulation view as drawn, as PNG; says how it
  /// went in the status bar or an error.
  bool saveBoxImageTo(const QString& path);
  /// The caption: "FooBall — gas, 300 balls, t = 6.00 s — runs: elastic (reference), exact".
  QString chartCaption() const;

 signals:
  /// Simulation → Single step took its step (the readouts show it already).
  void stepped();
  /// View → Reset layout.
  void resetLayoutRequested();

 private:
  void createActions();
  /// Edit → Undo and Redo, following the ball undo stack.
  void createUndoActions();
  void createMenus();
  /// The sidebar's drawing check boxes and compare layout choice set the View menu's actions.
  void followSidebar();
  void openSceneDialog();
  void saveSceneDialog();
  void exportChartsPng();
  void exportChartsCsv();
  void saveBoxImage();
  void openBenchmark();
  void openTradeoff();
  void openFailureMap();
  /// Wires a Tools dialog to the window: its runs pause the simulation, its points open.
  void connectTool(ToolDialog* dialog);
  /// A Tools run starts or ends: the simulation pauses while any runs (both would share the
  /// CPU) and continues after the last, unless it was paused before.
  void toolRunStarted();
  void toolRunFinished();

  Parts parts_;
  QAction* pause_ = nullptr;
  QAction* deleteBall_ = nullptr;
  QAction* undo_ = nullptr;
  QAction* redo_ = nullptr;
  QAction* step_ = nullptr;
  QAction* stepBack_ = nullptr;
  QAction* temperature_ = nullptr;
  QAction* tethers_ = nullptr;
  QAction* velocityVectors_ = nullptr;
  QAction* centreOfMass_ = nullptr;
  QAction* lookFor_ = nullptr;
  QAction* overlay_ = nullptr;
  QAction* sideBySide_ = nullptr;
  QAction* benchmark_ = nullptr;
  BenchmarkDialog* benchmarkDialog_ = nullptr;
  QAction* tradeoff_ = nullptr;
  TradeoffDialog* tradeoffDialog_ = nullptr;
  QAction* failureMap_ = nullptr;
  FailureMapDialog* failureMapDialog_ = nullptr;
  QAction* record_ = nullptr;
  RecordDialog* recordDialog_ = nullptr;
  int toolRuns_ = 0;             ///< Tools runs going
  bool pausedForTools_ = false;  ///< the Tools paused the runs and continue them
};

}  // namespace fooball::gui
