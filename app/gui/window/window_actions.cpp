#include "window/window_actions.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QMainWindow>
#include <QMenuBar>
#include <QUndoStack>

#include "charts/chart_panel.h"
#include "control/ball_commands.h"
#include "control/scene_commands.h"
#include "control/scene_session.h"
#include "frames/run_feed.h"
#include "recording/record_dialog.h"
#include "run/run_controller.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "tools/benchmark_dialog.h"
#include "tools/failure_map_dialog.h"
#include "tools/tradeoff_dialog.h"
#include "view/simulation_view.h"
#include "widgets/user_messages.h"
#include "window/help_dialogs.h"

namespace fooball::gui {

WindowActions::WindowActions(Parts parts) : QObject(&parts.window), parts_(parts) {
  createActions();
  createMenus();
  followSidebar();
}

void WindowActions::createActions() {
  pause_ = new QAction(tr("&Pause"), this);
  pause_->setCheckable(true);
  pause_->setShortcut(Qt::Key_Space);
  pause_->setToolTip(tr("Pause or continue every run (Space)"));
  connect(pause_, &QAction::toggled, &parts_.runs, &RunController::setPaused);

  step_ = new QAction(tr("Single &step"), this);
  step_->setShortcut(Qt::Key_Period);
  step_->setToolTip(tr("One physics step of every run while paused (.)"));
  step_->setEnabled(false);

  stepBack_ = new QAction(tr("Step &back"), this);
  stepBack_->setShortcut(Qt::Key_Comma);
  stepBack_->setToolTip(tr("Rewind every run one kept moment (0.1 s) while paused (,)"));
  stepBack_->setEnabled(false);
  connect(stepBack_, &QAction::triggered, &parts_.runs, &RunController::stepBack);

  createUndoActions();

  deleteBall_ = new QAction(tr("&Delete selected ball"), this);
  deleteBall_->setShortcut(QKeySequence::Delete);
  deleteBall_->setToolTip(tr("Remove the selected ball from every run (Delete)"));
  deleteBall_->setEnabled(false);
  connect(deleteBall_, &QAction::triggered, this, [this] {
    if (const auto selected = parts_.runs.group().selected()) parts_.balls.deleteBall(*selected);
  });
  connect(step_, &QAction::triggered, this, [this] {
    parts_.runs.stepOnce();
    parts_.feed.sampleCharts();
    parts_.feed.showReadouts();
    parts_.feed.showStatistics();
    parts_.feed.showSelectedBall();
    parts_.view.update();
    emit stepped();
  });

  SimulationView* view = &parts_.view;
  const auto drawingAction = [this, view](const QString& text, const QKeySequence& shortcut,
                                          void (SimulationView::*setter)(bool)) {
    auto* action = new QAction(text, this);
    action->setCheckable(true);
    action->setShortcut(shortcut);
    connect(action, &QAction::toggled, view, setter);
    connect(action, &QAction::toggled, this, [this, view] {
      parts_.sidebar.showDrawing(view->temperatureColouring(), view->tethers(),
                                 view->velocityVectors(), view->centreOfMass());
    });
    return action;
  };
  temperature_ = drawingAction(tr("&Temperature colouring"), QKeySequence(tr("Ctrl+T")),
                               &SimulationView::setTemperatureColouring);
  tethers_ = drawingAction(tr("Te&thers"), QKeySequence(tr("Ctrl+L")), &SimulationView::setTethers);
  velocityVectors_ = drawingAction(tr("&Velocity vectors"), QKeySequence(tr("Ctrl+Shift+V")),
                                   &SimulationView::setVelocityVectors);
  centreOfMass_ = drawingAction(tr("&Centre of mass"), QKeySequence(tr("Ctrl+M")),
                                &SimulationView::setCentreOfMass);
  tethers_->setChecked(true);

  lookFor_ = new QAction(tr("What to &look for"), this);
  lookFor_->setCheckable(true);
  lookFor_->setChecked(view->lookForShown());
  lookFor_->setShortcut(QKeySequence(tr("Ctrl+Shift+L")));
  lookFor_->setToolTip(tr("The preset's caption above the box: what to watch and what it proves"));
  connect(lookFor_, &QAction::toggled, view, &SimulationView::setLookForShown);
  connect(view, &SimulationView::lookForClosed, lookFor_, [this] { lookFor_->setChecked(false); });

  auto* layoutGroup = new QActionGroup(this);
  overlay_ = new QAction(tr("Compare: &overlay"), layoutGroup);
  sideBySide_ = new QAction(tr("Compare: side &by side"), layoutGroup);
  overlay_->setCheckable(true);
  sideBySide_->setCheckable(true);
  overlay_->setChecked(true);
  sideBySide_->setShortcut(QKeySequence(tr("Ctrl+Shift+B")));
  const auto useLayout = [this](CompareLayout layout) {
    parts_.view.setCompareLayout(layout);
    parts_.sidebar.runList()->showCompareLayout(layout);
  };
  connect(overlay_, &QAction::triggered, this, [useLayout] { useLayout(CompareLayout::Overlay); });
  connect(sideBySide_, &QAction::triggered, this,
          [useLayout] { useLayout(CompareLayout::SideBySide); });
}

void WindowActions::createUndoActions() {
  QUndoStack* stack = &parts_.undoStack;
  undo_ = new QAction(this);
  undo_->setShortcut(QKeySequence::Undo);
  redo_ = new QAction(this);
  redo_->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  connect(undo_, &QAction::triggered, this, [this] { parts_.balls.undo(); });
  connect(redo_, &QAction::triggered, this, [this] { parts_.balls.redo(); });
  // The text names the change, "Undo move of ball 7", as QUndoStack::createUndoAction's would;
  // these are our own actions so that a change that no longer fits is refused (ball_commands.h).
  const auto show = [this, stack] {
    undo_->setEnabled(stack->canUndo());
    undo_->setText(stack->canUndo() ? tr("&Undo %1").arg(stack->undoText()) : tr("&Undo"));
    redo_->setEnabled(stack->canRedo());
    redo_->setText(stack->canRedo() ? tr("&Redo %1").arg(stack->redoText()) : tr("&Redo"));
  };
  connect(stack, &QUndoStack::indexChanged, this, show);
  connect(stack, &QUndoStack::canUndoChanged, this, show);
  connect(stack, &QUndoStack::canRedoChanged, this, show);
  show();
  undo_->setToolTip(tr("Undo the last edit or delete of a ball (Ctrl+Z)"));
  redo_->setToolTip(tr("Redo what Undo undid (Ctrl+Shift+Z, Ctrl+Y)"));
}

void WindowActions::createMenus() {
  QMenuBar* bar = parts_.window.menuBar();
  QMenu* file = bar->addMenu(tr("&File"));
  file->addAction(tr("&Open scene…"), QKeySequence::Open, this, &WindowActions::openSceneDialog);
  file->addAction(tr("&Save scene as…"), QKeySequence::Save, this, &WindowActions::saveSceneDialog);
  file->addSeparator();
  file->addAction(tr("Export charts as &PNG…"), QKeySequence(tr("Ctrl+E")), this,
                  &WindowActions::exportChartsPng);
  file->addAction(tr("Export charts as &CSV…"), QKeySequence(tr("Ctrl+Shift+E")), this,
                  &WindowActions::exportChartsCsv);
  file->addAction(tr("Save &image of the box…"), this, &WindowActions::saveBoxImage);
  record_ = file->addAction(tr("&Record…"), this, &WindowActions::openRecord);
  record_->setToolTip(
      tr("Record the box, or the box and the charts, to MP4, WebM or an animated GIF"));
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, &parts_.window, &QWidget::close);

  QMenu* edit = bar->addMenu(tr("&Edit"));
  edit->addActions({undo_, redo_});

  QMenu* simulation = bar->addMenu(tr("&Simulation"));
  simulation->addAction(pause_);
  simulation->addAction(step_);
  simulation->addAction(stepBack_);
  // A field being edited keeps Delete for its text: Qt gives editors their editing keys first.
  simulation->addAction(deleteBall_);
  simulation->addSeparator();
  SceneSession* session = &parts_.session;
  simulation->addAction(tr("&Restart"), QKeySequence(tr("Ctrl+R")), session,
                        &SceneSession::restart);
  simulation->addAction(tr("Rese&t scene"), QKeySequence(tr("Ctrl+Shift+R")), session,
                        &SceneSession::resetScene);
  simulation->addAction(tr("Reset s&liders"), session, &SceneSession::resetSliders);
  simulation->addAction(tr("&Clear attractors"), QKeySequence(tr("Ctrl+Backspace")), session,
                        &SceneSession::clearAttractors);

  QMenu* viewMenu = bar->addMenu(tr("&View"));
  QAction* sidebarToggle = parts_.sidebarDock.toggleViewAction();
  sidebarToggle->setShortcut(QKeySequence(tr("Ctrl+1")));
  QAction* chartsToggle = parts_.chartsDock.toggleViewAction();
  chartsToggle->setShortcut(QKeySequence(tr("Ctrl+2")));
  QAction* statisticsToggle = parts_.statisticsDock.toggleViewAction();
  statisticsToggle->setShortcut(QKeySequence(tr("Ctrl+3")));
  statisticsToggle->setToolTip(
      tr("Speed histogram against Maxwell–Boltzmann, temperature, pressure and collision rate "
         "against the hard-disk theory (Ctrl+3)"));
  viewMenu->addActions({sidebarToggle, chartsToggle, statisticsToggle});
  QAction* focusBox = viewMenu->addAction(tr("&Focus the box"), QKeySequence(Qt::Key_Escape),
                                          &parts_.view, qOverload<>(&QWidget::setFocus));
  focusBox->setToolTip(tr("Give the keyboard back to the box (Esc): Space pauses, '.' steps"));
  QAction* resetLayout =
      viewMenu->addAction(tr("Reset &layout"), this, &WindowActions::resetLayoutRequested);
  resetLayout->setToolTip(
      tr("Put the settings and charts back where they were at first start, statistics closed"));
  viewMenu->addSeparator();
  viewMenu->addActions({temperature_, tethers_, velocityVectors_, centreOfMass_});
  viewMenu->addAction(lookFor_);
  viewMenu->addSeparator();
  viewMenu->addActions({overlay_, sideBySide_});

  QMenu* tools = bar->addMenu(tr("&Tools"));
  benchmark_ = tools->addAction(tr("&Benchmark…"), this, &WindowActions::openBenchmark);
  benchmark_->setToolTip(
      tr("Measure how many balls each backend steps within a time budget (fooball-cli capacity)"));
  tradeoff_ = tools->addAction(tr("&Speed vs accuracy…"), this, &WindowActions::openTradeoff);
  tradeoff_->setToolTip(
      tr("Measure what each backend's settings cost and get wrong on a scene "
         "(fooball-cli tradeoff)"));
  failureMap_ = tools->addAction(tr("&Failure map…"), this, &WindowActions::openFailureMap);
  failureMap_->setToolTip(
      tr("Find where each method starts to fail as scenes get harder (fooball-cli failure-map)"));

  QMenu* help = bar->addMenu(tr("&Help"));
  help->addAction(tr("&Mouse and keys"), QKeySequence::HelpContents, this,
                  [this, bar] { showMouseAndKeys(&parts_.window, *bar); });
  help->addAction(tr("&Reading the charts"), this,
                  [this] { showReadingTheCharts(&parts_.window); });
  help->addAction(tr("&About FooBall"), this, [this] { showAbout(&parts_.window); });
  help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);

  for (QMenu* menu : {file, edit, simulation, viewMenu, tools, help})
    menu->setToolTipsVisible(true);
}

void WindowActions::followSidebar() {
  const SettingsSidebar* sidebar = &parts_.sidebar;
  connect(sidebar, &SettingsSidebar::temperatureToggled, temperature_, &QAction::setChecked);
  connect(sidebar, &SettingsSidebar::tethersToggled, tethers_, &QAction::setChecked);
  connect(sidebar, &SettingsSidebar::velocityVectorsToggled, velocityVectors_,
          &QAction::setChecked);
  connect(sidebar, &SettingsSidebar::centreOfMassToggled, centreOfMass_, &QAction::setChecked);
  connect(sidebar->runList(), &RunListEditor::compareLayoutChosen, this,
          [this](CompareLayout layout) {
            (layout == CompareLayout::Overlay ? overlay_ : sideBySide_)->setChecked(true);
            parts_.view.setCompareLayout(layout);
          });
}

void WindowActions::applyShowOptions(const QStringList& show) {
  if (show.contains(QStringLiteral("temperature"))) temperature_->setChecked(true);
  if (show.contains(QStringLiteral("vectors"))) velocityVectors_->setChecked(true);
  if (show.contains(QStringLiteral("centre-of-mass"))) centreOfMass_->setChecked(true);
  if (show.contains(QStringLiteral("side-by-side"))) sideBySide_->trigger();
  // In front of the charts' tab (MainWindow::createDocks).
  if (show.contains(QStringLiteral("statistics"))) parts_.statisticsDock.show();
}

void WindowActions::showPaused(bool paused) {
  pause_->setChecked(paused);
  pause_->setText(paused ? tr("&Continue") : tr("&Pause"));
  step_->setEnabled(paused);
  stepBack_->setEnabled(paused);
}

void WindowActions::openSceneDialog() {
  const QString path = QFileDialog::getOpenFileName(&parts_.window, tr("Open scene"), QString(),
                                                    tr("FooBall scenes (*.json);;All files (*)"));
  if (!path.isEmpty()) parts_.scenes.openSceneFile(path);
}

void WindowActions::saveSceneDialog() {
  const QString path = QFileDialog::getSaveFileName(&parts_.window, tr("Save scene"), QString(),
                                                    tr("FooBall scenes (*.json)"));
  if (!path.isEmpty()) parts_.scenes.saveSceneFile(path);
}

void WindowActions::exportChartsPng() {
  const QString path = QFileDialog::getSaveFileName(&parts_.window, tr("Export charts as PNG"),
                                                    QString(), tr("PNG images (*.png)"));
  if (!path.isEmpty()) exportChartsPngTo(path);
}

bool WindowActions::exportChartsPngTo(const QString& path) {
  if (!parts_.charts.exportPng(path, chartCaption())) {
    parts_.messages.reportError(tr("Could not export the charts"),
                                tr("Could not write %1").arg(path));
    return false;
  }
  parts_.messages.showStatus(tr("Charts saved to %1").arg(path));
  return true;
}

void WindowActions::saveBoxImage() {
  const QString path = QFileDialog::getSaveFileName(&parts_.window, tr("Save image of the box"),
                                                    QString(), tr("PNG images (*.png)"));
  if (!path.isEmpty()) saveBoxImageTo(path);
}

bool WindowActions::saveBoxImageTo(const QString& path) {
  if (!parts_.view.grab().save(path, "PNG")) {
    parts_.messages.reportError(tr("Could not save the image of the box"),
                                tr("Could not write %1").arg(path));
    return false;
  }
  parts_.messages.showStatus(tr("Image of the box saved to %1").arg(path));
  return true;
}

QString WindowActions::chartCaption() const {
  const RunController& runs = parts_.runs;
  QStringList labels = runs.labels();
  if (labels.size() > 1) labels.front() += tr(" (reference)");
  if (runs.group().hasBaseline()) labels.append(tr("chaos baseline"));
  return tr("FooBall — %1, %2 balls, t = %3 s — %4: %5")
      .arg(parts_.session.sourceName())
      .arg(runs.group().ballCount())
      .arg(runs.group().time(), 0, 'f', 2)
      .arg(labels.size() > 1 ? tr("runs") : tr("run"), labels.join(QStringLiteral(", ")));
}

void WindowActions::exportChartsCsv() {
  const QString path = QFileDialog::getSaveFileName(&parts_.window, tr("Export charts as CSV"),
                                                    QString(), tr("CSV files (*.csv)"));
  if (path.isEmpty()) return;
  if (parts_.charts.exportCsv(path)) {
    parts_.messages.showStatus(tr("Chart data saved to %1").arg(path));
  } else {
    parts_.messages.reportError(tr("Could not export the chart data"),
                                tr("Could not write %1").arg(path));
  }
}

namespace {

void showTool(QDialog* dialog) {
  dialog->show();
  dialog->raise();
  dialog->activateWindow();
}

}  // namespace

RecordDialog* WindowActions::openRecord() {
  if (!recordDialog_) {
    recordDialog_ = new RecordDialog(parts_.recording, parts_.window);
    connect(recordDialog_, &RecordDialog::errorToReport, &parts_.messages,
            &UserMessages::reportError);
    connect(recordDialog_, &RecordDialog::statusToShow, &parts_.messages,
            &UserMessages::showStatus);
  }
  showTool(recordDialog_);
  return recordDialog_;
}

void WindowActions::openBenchmark() {
  if (!benchmarkDialog_) {
    benchmarkDialog_ = new BenchmarkDialog(&parts_.window);
    connect(benchmarkDialog_, &BenchmarkDialog::runStarted, this, &WindowActions::toolRunStarted);
    connect(benchmarkDialog_, &BenchmarkDialog::runFinished, this, &WindowActions::toolRunFinished);
  }
  showTool(benchmarkDialog_);
}

void WindowActions::openTradeoff() {
  if (!tradeoffDialog_) {
    tradeoffDialog_ = new TradeoffDialog(&parts_.window);
    connectTool(tradeoffDialog_);
  }
  showTool(tradeoffDialog_);
}

void WindowActions::openFailureMap() {
  if (!failureMapDialog_) {
    failureMapDialog_ = new FailureMapDialog(&parts_.window);
    connectTool(failureMapDialog_);
  }
  showTool(failureMapDialog_);
}

void WindowActions::connectTool(ToolDialog* dialog) {
  connect(dialog, &ToolDialog::runStarted, this, &WindowActions::toolRunStarted);
  connect(dialog, &ToolDialog::runFinished, this, &WindowActions::toolRunFinished);
  connect(dialog, &ToolDialog::openRequested, this, [this](const Configuration& configuration) {
    parts_.scenes.openConfiguration(configuration);
  });
}

void WindowActions::toolRunStarted() {
  // The measurements and the simulation would share the CPU: the runs pause meanwhile.
  if (toolRuns_++ == 0) {
    pausedForTools_ = !parts_.runs.paused();
    if (pausedForTools_) parts_.runs.setPaused(true);
  }
  parts_.messages.showStatus(tr("Paused while the measurement runs"));
}

void WindowActions::toolRunFinished() {
  if (--toolRuns_ > 0) return;
  if (pausedForTools_) parts_.runs.setPaused(false);
  pausedForTools_ = false;
}

void WindowActions::closeTools() {
  for (QDialog* dialog :
       std::initializer_list<QDialog*>{benchmarkDialog_, tradeoffDialog_, failureMapDialog_}) {
    if (dialog) dialog->close();
  }
  if (recordDialog_) recordDialog_->stop();  // the file finished before the window goes
}

void WindowActions::destroyTools() {
  delete benchmarkDialog_;
  benchmarkDialog_ = nullptr;
  delete tradeoffDialog_;
  tradeoffDialog_ = nullptr;
  delete failureMapDialog_;
  failureMapDialog_ = nullptr;
  delete recordDialog_;  // its recording, if any, finishes its file
  recordDialog_ = nullptr;
}

}  // namespace fooball::gui
