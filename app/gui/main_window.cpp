#include "main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QShowEvent>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <exception>

#include "backend_options_form.h"
#include "ball_inspector.h"
#include "benchmark_dialog.h"
#include "charts/chart_panel.h"
#include "compare_readout.h"
#include "fooball/presets.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "help_dialogs.h"
#include "number_format.h"
#include "run_controller.h"
#include "settings_sidebar.h"
#include "simulation_view.h"

namespace fooball::gui {

namespace {

constexpr double kDefaultStrength = 10.0;  // 1/s², as Interactions starts
constexpr double kDefaultTimeScale = 1.0;
constexpr int kFrameIntervalMs = 16;      // ~60 frames/s
constexpr double kMaxFrameSeconds = 0.1;  // a stall longer than this is not caught up
/// Charts get a sample every few frames: 20 per second at 60 frames/s is smooth, and keeps
/// the O(N) metrics (overlap search included) off most frames at 100,000 balls.
constexpr int kFramesPerSample = 3;
/// s a step may run in the background before the status bar says how to give it up.
constexpr double kSlowStepNoticeSeconds = 1.0;
constexpr int kFramesPerReadout = 6;  // compare readout and inspector: 10 per second
constexpr int kStatusMessageMs = 8000;
constexpr int kSidebarWidth = 330;  // px

QString modeName(MouseMode mode) {
  switch (mode) {
    case MouseMode::Attract:
      return QObject::tr("attract");
    case MouseMode::Repel:
      return QObject::tr("repel");
    case MouseMode::Grab:
      return QObject::tr("grab");
    case MouseMode::Slingshot:
      return QObject::tr("slingshot");
  }
  return {};
}

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(QFile::encodeName(path).toStdString());
}

}  // namespace

MainWindow::MainWindow(const StartupOptions& options, QWidget* parent)
    : QMainWindow(parent),
      runs_(std::make_unique<RunController>(options.scene, options.backend)),
      rememberSettings_(options.rememberSettings),
      presetName_(options.presetName),
      sourceName_(options.sourceName) {
  setObjectName(QStringLiteral("mainWindow"));
  reportError_ = [this](const QString& title, const QString& message) {
    QMessageBox::warning(this, title, message);
  };

  view_ = new SimulationView(*runs_);
  compareReadout_ = new CompareReadout;
  compareReadout_->hide();
  auto* central = new QWidget;
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(compareReadout_);
  layout->addWidget(view_, 1);
  setCentralWidget(central);

  createDocks();
  createActions();
  createMenus();
  createStatusBar();
  connectSidebar();
  connectView();
  connectRuns();

  frameTimer_ = new QTimer(this);
  frameTimer_->setTimerType(Qt::PreciseTimer);
  frameTimer_->setInterval(kFrameIntervalMs);
  connect(frameTimer_, &QTimer::timeout, this, [this] {
    const double elapsed = std::min(double(frameClock_.nsecsElapsed()) * 1e-9, kMaxFrameSeconds);
    frameClock_.restart();
    advanceFrame(elapsed);
  });

  runs_->setStrength(kDefaultStrength);
  resize(1440, 900);
  if (rememberSettings_) readSettings();
  if (options.balls) runs_->setBallCount(*options.balls);
  if (!options.compare.isEmpty()) runs_->startCompare(options.compare);
  for (const Vec2 point : options.attractors)
    runs_->addAttractor(point);
  if (options.show.contains(QStringLiteral("temperature"))) temperatureAction_->setChecked(true);
  if (options.show.contains(QStringLiteral("vectors"))) velocityVectorsAction_->setChecked(true);
  if (options.show.contains(QStringLiteral("centre-of-mass")))
    centreOfMassAction_->setChecked(true);
  if (options.show.contains(QStringLiteral("side-by-side"))) sideBySideAction_->trigger();

  syncSidebar();
  resetCharts();
  updateTitle();
  updateStatusBar();
}

MainWindow::~MainWindow() {
  // The widgets go first: they refer to the runs, and a field losing focus as it is destroyed
  // still reports an edit. The benchmark first of all: it stops and joins its thread.
  delete benchmark_;
  delete sidebarDock_;
  delete chartsDock_;
  delete takeCentralWidget();
}

void MainWindow::createDocks() {
  sidebar_ = new SettingsSidebar;
  sidebarScroll_ = new QScrollArea;
  sidebarScroll_->setWidget(sidebar_);
  sidebarScroll_->setWidgetResizable(true);
  sidebarScroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  sidebarScroll_->setMinimumWidth(sidebar_->sizeHint().width() + 24);
  sidebarDock_ = new QDockWidget(tr("Settings"), this);
  sidebarDock_->setObjectName(QStringLiteral("settingsDock"));
  sidebarDock_->setWidget(sidebarScroll_);
  addDockWidget(Qt::RightDockWidgetArea, sidebarDock_);

  charts_ = new ChartPanel;
  chartsDock_ = new QDockWidget(tr("Charts"), this);
  chartsDock_->setObjectName(QStringLiteral("chartsDock"));
  chartsDock_->setWidget(charts_);
  addDockWidget(Qt::BottomDockWidgetArea, chartsDock_);
  // The settings column runs the full height; the charts sit under the view.
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
}

void MainWindow::createActions() {
  pauseAction_ = new QAction(tr("&Pause"), this);
  pauseAction_->setCheckable(true);
  pauseAction_->setShortcut(Qt::Key_Space);
  pauseAction_->setToolTip(tr("Pause or continue every run (Space)"));
  connect(pauseAction_, &QAction::toggled, runs_.get(), &RunController::setPaused);

  stepAction_ = new QAction(tr("Single &step"), this);
  stepAction_->setShortcut(Qt::Key_Period);
  stepAction_->setToolTip(tr("One physics step of every run while paused (.)"));
  stepAction_->setEnabled(false);
  connect(stepAction_, &QAction::triggered, this, [this] {
    runs_->stepOnce();
    sampleCharts();
    showSelectedBall();
    view_->update();
    updateStatusBar();
  });

  const auto drawingAction = [this](const QString& text, const QKeySequence& shortcut,
                                    void (SimulationView::*setter)(bool)) {
    auto* action = new QAction(text, this);
    action->setCheckable(true);
    action->setShortcut(shortcut);
    connect(action, &QAction::toggled, view_, setter);
    return action;
  };
  temperatureAction_ = drawingAction(tr("&Temperature colouring"), QKeySequence(tr("Ctrl+T")),
                                     &SimulationView::setTemperatureColouring);
  tethersAction_ =
      drawingAction(tr("Te&thers"), QKeySequence(tr("Ctrl+L")), &SimulationView::setTethers);
  velocityVectorsAction_ = drawingAction(tr("&Velocity vectors"), QKeySequence(tr("Ctrl+Shift+V")),
                                         &SimulationView::setVelocityVectors);
  centreOfMassAction_ = drawingAction(tr("&Centre of mass"), QKeySequence(tr("Ctrl+M")),
                                      &SimulationView::setCentreOfMass);
  tethersAction_->setChecked(true);

  auto* layoutGroup = new QActionGroup(this);
  overlayAction_ = new QAction(tr("Compare: &overlay"), layoutGroup);
  sideBySideAction_ = new QAction(tr("Compare: side &by side"), layoutGroup);
  overlayAction_->setCheckable(true);
  sideBySideAction_->setCheckable(true);
  overlayAction_->setChecked(true);
  sideBySideAction_->setShortcut(QKeySequence(tr("Ctrl+Shift+B")));
  connect(overlayAction_, &QAction::triggered, this, [this] {
    view_->setCompareLayout(CompareLayout::Overlay);
    sidebar_->showCompareLayout(CompareLayout::Overlay);
  });
  connect(sideBySideAction_, &QAction::triggered, this, [this] {
    view_->setCompareLayout(CompareLayout::SideBySide);
    sidebar_->showCompareLayout(CompareLayout::SideBySide);
  });
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open scene…"), QKeySequence::Open, this, &MainWindow::openSceneDialog);
  file->addAction(tr("&Save scene as…"), QKeySequence::Save, this, &MainWindow::saveSceneDialog);
  file->addSeparator();
  file->addAction(tr("Export charts as &PNG…"), QKeySequence(tr("Ctrl+E")), this,
                  &MainWindow::exportChartsPng);
  file->addAction(tr("Export charts as &CSV…"), QKeySequence(tr("Ctrl+Shift+E")), this,
                  &MainWindow::exportChartsCsv);
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
  simulation->addAction(pauseAction_);
  simulation->addAction(stepAction_);
  simulation->addSeparator();
  simulation->addAction(tr("&Restart"), QKeySequence(tr("Ctrl+R")), this, [this] {
    runs_->restart();
    resetCharts();
  });
  simulation->addAction(tr("Rese&t scene"), QKeySequence(tr("Ctrl+Shift+R")), this,
                        &MainWindow::resetScene);
  simulation->addAction(tr("Reset s&liders"), this, &MainWindow::resetSliders);
  simulation->addAction(tr("&Clear attractors"), QKeySequence(tr("Ctrl+Backspace")), this, [this] {
    runs_->clearAttractors();
    sidebar_->showAttractorCount(0);
  });

  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  QAction* sidebarToggle = sidebarDock_->toggleViewAction();
  sidebarToggle->setShortcut(QKeySequence(tr("Ctrl+1")));
  QAction* chartsToggle = chartsDock_->toggleViewAction();
  chartsToggle->setShortcut(QKeySequence(tr("Ctrl+2")));
  viewMenu->addAction(sidebarToggle);
  viewMenu->addAction(chartsToggle);
  viewMenu->addSeparator();
  viewMenu->addAction(temperatureAction_);
  viewMenu->addAction(tethersAction_);
  viewMenu->addAction(velocityVectorsAction_);
  viewMenu->addAction(centreOfMassAction_);
  viewMenu->addSeparator();
  viewMenu->addAction(overlayAction_);
  viewMenu->addAction(sideBySideAction_);

  QMenu* tools = menuBar()->addMenu(tr("&Tools"));
  benchmarkAction_ = tools->addAction(tr("&Benchmark…"), this, &MainWindow::openBenchmark);
  benchmarkAction_->setToolTip(
      tr("Measure how many balls each backend steps within a time budget (fooball-cli capacity)"));

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Mouse and keys"), QKeySequence::HelpContents, this,
                  [this] { showMouseAndKeys(this); });
  help->addAction(tr("&About FooBall"), this, [this] { showAbout(this); });
  help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);

  for (QMenu* menu : {file, simulation, viewMenu, tools, help})
    menu->setToolTipsVisible(true);
}

void MainWindow::createStatusBar() {
  const auto addField = [this](QLabel*& label, const QString& toolTip) {
    label = new QLabel;
    label->setToolTip(toolTip);
    statusBar()->addPermanentWidget(label);
  };
  addField(cursorStatus_, tr("Where the cursor is in the box, in metres (origin bottom-left)"));
  addField(backendStatus_, tr("The backend of each run"));
  addField(ballsStatus_, tr("Balls in the scene"));
  addField(timeStatus_, tr("Simulated time since the scene started"));
  addField(stepsStatus_, tr("Physics steps per second of wall time (per run)"));
  addField(framesStatus_, tr("Frames drawn per second"));
  addField(stepCostStatus_, tr("Wall-clock milliseconds one physics step costs, per run"));
  statusTimer_ = new QTimer(this);
  statusTimer_->setInterval(250);
  connect(statusTimer_, &QTimer::timeout, this, &MainWindow::updateStatusBar);
}

void MainWindow::connectSidebar() {
  SettingsSidebar* s = sidebar_;
  connect(s, &SettingsSidebar::presetChosen, this, &MainWindow::openPreset);
  connect(s, &SettingsSidebar::ballCountChosen, this,
          [this](int count) { setBallCount(static_cast<std::size_t>(count)); });
  connect(s, &SettingsSidebar::restartRequested, this, [this] {
    runs_->restart();
    resetCharts();
  });
  connect(s, &SettingsSidebar::resetSceneRequested, this, &MainWindow::resetScene);
  connect(s, &SettingsSidebar::backendChosen, this, &MainWindow::chooseBackend);
  connect(s, &SettingsSidebar::compareChosen, this, &MainWindow::chooseCompare);
  connect(s, &SettingsSidebar::backendOptionChanged, this,
          [this](int runIndex, const QString& name, double value) {
            try {
              runs_->setBackendOption(runIndex, name, value);
              markChange(QStringLiteral("%1 = %2").arg(name, formatNumber(value)));
            } catch (const std::invalid_argument& error) {
              showStatus(QString::fromStdString(error.what()));
              sidebar_->optionsForm(runIndex)->showOptions(runs_->run(runIndex).backend());
            }
          });

  connect(s, &SettingsSidebar::gravityChosen, this, &MainWindow::applyGravity);
  connect(s, &SettingsSidebar::airResistanceChosen, this, [this](double coefficient) {
    WorldSettings world = runs_->world();
    world.airResistance = coefficient;
    runs_->setWorld(world);
    markChange(tr("air resistance %1 1/s").arg(formatNumber(coefficient)));
  });
  connect(s, &SettingsSidebar::strengthChosen, this, [this](double strength) {
    runs_->setStrength(strength);
    markChange(tr("mouse strength %1").arg(formatNumber(strength)));
  });
  connect(s, &SettingsSidebar::timeScaleChosen, this, &MainWindow::setTimeScale);
  connect(s, &SettingsSidebar::resetSlidersRequested, this, &MainWindow::resetSliders);
  connect(s, &SettingsSidebar::ballCollisionsToggled, this, [this](bool on) {
    WorldSettings world = runs_->world();
    world.ballCollisions = on;
    runs_->setWorld(world);
    markChange(on ? tr("collisions on") : tr("collisions off"));
  });
  connect(s, &SettingsSidebar::wallsToggled, this, [this](bool on) {
    WorldSettings world = runs_->world();
    world.walls = Walls{on, on, on, on};
    runs_->setWorld(world);
    markChange(on ? tr("walls on") : tr("walls off"));
    view_->update();
  });

  connect(s, &SettingsSidebar::mouseModeChosen, runs_.get(), &RunController::setMouseMode);
  connect(s, &SettingsSidebar::scopeChosen, runs_.get(), &RunController::setScope);
  connect(s, &SettingsSidebar::clearAttractorsRequested, this, [this] {
    runs_->clearAttractors();
    sidebar_->showAttractorCount(0);
    view_->update();
  });

  // The drawing check boxes and the View menu's actions mirror each other.
  const auto mirror = [this](void (SettingsSidebar::*signal)(bool), QAction* action) {
    connect(sidebar_, signal, action, &QAction::setChecked);
  };
  mirror(&SettingsSidebar::temperatureToggled, temperatureAction_);
  mirror(&SettingsSidebar::tethersToggled, tethersAction_);
  mirror(&SettingsSidebar::velocityVectorsToggled, velocityVectorsAction_);
  mirror(&SettingsSidebar::centreOfMassToggled, centreOfMassAction_);
  for (QAction* action :
       {temperatureAction_, tethersAction_, velocityVectorsAction_, centreOfMassAction_}) {
    connect(action, &QAction::toggled, this, [this] {
      sidebar_->showDrawing(view_->temperatureColouring(), view_->tethers(),
                            view_->velocityVectors(), view_->centreOfMass());
    });
  }
  connect(s, &SettingsSidebar::compareLayoutChosen, this, [this](CompareLayout layout) {
    (layout == CompareLayout::Overlay ? overlayAction_ : sideBySideAction_)->setChecked(true);
    view_->setCompareLayout(layout);
  });

  BallInspector* inspector = s->inspector();
  connect(inspector, &BallInspector::ballEdited, this,
          [this](std::size_t index, const BallDef& ball) {
            try {
              runs_->setBall(index, ball);
              markChange(tr("ball #%1 edited").arg(index));
            } catch (const SceneError& error) {
              const QString message = QString::fromStdString(error.what());
              sidebar_->inspector()->showBall(index, runs_->ball(index), true);
              sidebar_->inspector()->showError(message);
              showStatus(message);
            }
            showSelectedBall();
            view_->update();
          });
  connect(inspector, &BallInspector::deleteRequested, this, [this](std::size_t index) {
    runs_->deleteBall(index);
    markChange(tr("ball #%1 deleted").arg(index));
  });
}

void MainWindow::connectView() {
  connect(view_, &SimulationView::toolPressed, this, [this](Vec2 point) {
    runs_->pressTool(point);
    markChange(modeName(runs_->interactions().mode));
  });
  connect(view_, &SimulationView::toolMoved, runs_.get(), &RunController::moveTool);
  connect(view_, &SimulationView::toolReleased, runs_.get(), &RunController::releaseTool);
  connect(view_, &SimulationView::attractorPlaced, this, [this](Vec2 point) {
    runs_->addAttractor(point);
    sidebar_->showAttractorCount(runs_->interactions().attractors().size());
    markChange(tr("attractor"));
  });
  connect(view_, &SimulationView::ballClicked, runs_.get(), &RunController::setSelected);
  connect(view_, &SimulationView::cursorMoved, this, [this](Vec2 point) {
    cursorStatus_->setText(
        tr("x = %1 m, y = %2 m").arg(point.x, 0, 'f', 2).arg(point.y, 0, 'f', 2));
  });
}

void MainWindow::connectRuns() {
  connect(runs_.get(), &RunController::pausedChanged, this, [this](bool paused) {
    pauseAction_->setChecked(paused);
    pauseAction_->setText(paused ? tr("&Continue") : tr("&Pause"));
    stepAction_->setEnabled(paused);
    frameClock_.restart();
    view_->update();
  });
  connect(runs_.get(), &RunController::selectionChanged, this,
          [this](std::optional<std::size_t> index) {
            showSelectedBall();
            if (index) sidebarScroll_->ensureWidgetVisible(sidebar_->inspector());
            view_->update();
          });
  connect(runs_.get(), &RunController::ballsChanged, this, [this] {
    sidebar_->showBallCount(runs_->ballCount());
    showSelectedBall();
    view_->update();
  });
  connect(runs_.get(), &RunController::runsChanged, this, [this] {
    sidebar_->showBackends(runs_->backendName(0),
                           runs_->comparing() ? runs_->backendName(1) : QString());
    sidebar_->optionsForm(0)->showOptions(runs_->run(0).backend());
    if (runs_->comparing()) sidebar_->optionsForm(1)->showOptions(runs_->run(1).backend());
    compareReadout_->setVisible(runs_->comparing());
    if (runs_->comparing()) {
      compareReadout_->showRuns(runs_->backendName(0), runs_->backendName(1));
      compareReadout_->showDivergence(runs_->divergence());
    }
    updateTitle();
    updateStatusBar();
    view_->update();
  });
}

void MainWindow::syncSidebar() {
  sidebar_->showSceneSource(presetName_, sourceName_);
  sidebar_->showBallCount(runs_->ballCount());
  sidebar_->showWorld(runs_->world());
  sidebar_->showStrength(runs_->interactions().strength);
  sidebar_->showTimeScale(timeScale_);
  sidebar_->showMouseMode(runs_->interactions().mode);
  sidebar_->showScope(runs_->interactions().scope);
  sidebar_->showBackends(runs_->backendName(0),
                         runs_->comparing() ? runs_->backendName(1) : QString());
  sidebar_->optionsForm(0)->showOptions(runs_->run(0).backend());
  if (runs_->comparing()) sidebar_->optionsForm(1)->showOptions(runs_->run(1).backend());
  sidebar_->showAttractorCount(runs_->interactions().attractors().size());
  sidebar_->showDrawing(view_->temperatureColouring(), view_->tethers(), view_->velocityVectors(),
                        view_->centreOfMass());
  sidebar_->showCompareLayout(view_->compareLayout());
  compareReadout_->setVisible(runs_->comparing());
  if (runs_->comparing()) {
    compareReadout_->showRuns(runs_->backendName(0), runs_->backendName(1));
    compareReadout_->showDivergence(runs_->divergence());
  }
  showSelectedBall();
}

void MainWindow::showSelectedBall() {
  const auto selected = runs_->selected();
  sidebar_->showSelection(selected, selected ? runs_->ball(*selected) : BallDef{});
}

void MainWindow::resetCharts() {
  charts_->reset(runs_->backendNames());
  framesSinceSample_ = 0;
  sampleCharts();
}

void MainWindow::sampleCharts() {
  for (int i = 0; i < runs_->runCount(); ++i)
    charts_->addSample(i, runs_->run(i).metrics());
}

void MainWindow::markChange(const QString& label) {
  charts_->addMarker(runs_->time(), label);
}

void MainWindow::showStatus(const QString& message) {
  statusBar()->showMessage(message, kStatusMessageMs);
}

void MainWindow::loadScene(const Scene& scene, const QString& presetName,
                           const QString& sourceName) {
  presetName_ = presetName;
  sourceName_ = sourceName;
  runs_->loadScene(scene);
  syncSidebar();
  resetCharts();
  updateTitle();
}

bool MainWindow::openSceneFile(const QString& path) {
  try {
    const Scene scene = loadSceneFile(toPath(path));
    loadScene(scene, QString(), QFileInfo(path).fileName());
    showStatus(tr("Opened %1: %2 balls").arg(path).arg(scene.balls.size()));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    showStatus(tr("Could not open the scene; the current one stays: %1").arg(message));
    reportError_(tr("Could not open the scene"), message);
    return false;
  }
}

bool MainWindow::saveSceneFile(const QString& path) {
  try {
    fooball::saveSceneFile(runs_->run(0).scene(), toPath(path));
    showStatus(tr("Saved %1").arg(path));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    showStatus(message);
    reportError_(tr("Could not save the scene"), message);
    return false;
  }
}

bool MainWindow::openPreset(const QString& name) {
  try {
    loadScene(loadPreset(name.toStdString()), name, name);
    return true;
  } catch (const SceneError& error) {
    const QString message = QString::fromStdString(error.what());
    showStatus(message);
    reportError_(tr("Could not load the preset"), message);
    syncSidebar();
    return false;
  }
}

bool MainWindow::setBallCount(std::size_t count) {
  const std::size_t before = runs_->ballCount();
  try {
    runs_->setBallCount(count);
  } catch (const SceneError& error) {
    showStatus(QString::fromStdString(error.what()));
    sidebar_->showBallCount(runs_->ballCount());
    return false;
  }
  if (count != before) markChange(tr("%1 balls").arg(count));
  if (count > before && runs_->newBallScale() < 1.0) {
    showStatus(tr("Added %L1 balls at %2 % of the size of the balls there, so that they fit")
                   .arg(count - before)
                   .arg(100.0 * runs_->newBallScale(), 0, 'g', 2));
  }
  return true;
}

void MainWindow::applyGravity(double magnitude) {
  WorldSettings world = runs_->world();
  // Keep the direction gravity has (or had in the scene); straight down when there is none.
  Vec2 direction{0.0, -1.0};
  const Vec2 loaded = runs_->loadedScene().world.gravity;
  if (length(world.gravity) > 0.0) {
    direction = world.gravity / length(world.gravity);
  } else if (length(loaded) > 0.0) {
    direction = loaded / length(loaded);
  }
  world.gravity = magnitude * direction;
  runs_->setWorld(world);
  markChange(tr("gravity %1 m/s²").arg(formatNumber(magnitude)));
}

void MainWindow::setTimeScale(double timeScale) {
  timeScale_ = timeScale;
  markChange(tr("speed %1×").arg(formatNumber(timeScale)));
}

void MainWindow::chooseBackend(const QString& name) {
  if (name == runs_->backendName(0)) return;
  try {
    runs_->setBackend(RunController::kMainRun, name);
    markChange(tr("backend → %1").arg(name));
  } catch (const std::exception& error) {
    showStatus(QString::fromStdString(error.what()));
    sidebar_->showBackends(runs_->backendName(0),
                           runs_->comparing() ? runs_->backendName(1) : QString());
  }
}

void MainWindow::chooseCompare(const QString& name) {
  try {
    if (name.isEmpty()) {
      runs_->stopCompare();
    } else {
      runs_->startCompare(name);
    }
  } catch (const std::exception& error) {
    showStatus(QString::fromStdString(error.what()));
  }
  resetCharts();
}

void MainWindow::resetSliders() {
  WorldSettings world = runs_->world();
  world.gravity = runs_->loadedScene().world.gravity;
  world.airResistance = runs_->loadedScene().world.airResistance;
  runs_->setWorld(world);
  runs_->setStrength(kDefaultStrength);
  timeScale_ = kDefaultTimeScale;
  sidebar_->showWorld(runs_->world());
  sidebar_->showStrength(kDefaultStrength);
  sidebar_->showTimeScale(timeScale_);
  markChange(tr("sliders reset"));
}

void MainWindow::resetScene() {
  runs_->loadScene(runs_->loadedScene());
  runs_->setStrength(kDefaultStrength);
  timeScale_ = kDefaultTimeScale;
  syncSidebar();
  resetCharts();
}

void MainWindow::advanceFrame(double elapsedSeconds) {
  const int steps = runs_->advance(elapsedSeconds, timeScale_);
  frameRate_.addFrame(steps);
  if (steps > 0) {
    if (++framesSinceSample_ >= kFramesPerSample) {
      framesSinceSample_ = 0;
      sampleCharts();
    }
    if (++framesSinceReadout_ >= kFramesPerReadout) {
      framesSinceReadout_ = 0;
      if (runs_->comparing()) compareReadout_->showDivergence(runs_->divergence());
      if (runs_->selected()) showSelectedBall();
    }
  }
  view_->update();
}

void MainWindow::startLiveUpdates() {
  frameClock_.start();
  frameTimer_->start();
  statusTimer_->start();
}

void MainWindow::updateStatusBar() {
  const int count = runs_->runCount();
  QStringList backends;
  QStringList costs;
  for (int i = 0; i < count; ++i) {
    backends << runs_->backendName(i);
    costs << QString::number(runs_->stepTiming(i).millisecondsPerStep, 'f', 2);
  }
  const double stepSeconds = runs_->stepSeconds();
  if (stepSeconds >= kSlowStepNoticeSeconds) {
    showStatus(tr("One physics step has taken %1 s so far. Pause (Space) gives it up.")
                   .arg(stepSeconds, 0, 'f', 1));
  }
  backendStatus_->setText(backends.join(tr(" vs ")));
  ballsStatus_->setText(tr("%L1 balls").arg(runs_->ballCount()));
  timeStatus_->setText(tr("t = %1 s").arg(runs_->time(), 0, 'f', 2));
  stepsStatus_->setText(tr("%1 steps/s").arg(frameRate_.stepsPerSecond(), 0, 'f', 0));
  framesStatus_->setText(tr("%1 frames/s").arg(frameRate_.framesPerSecond(), 0, 'f', 0));
  stepCostStatus_->setText(runs_->stepping()
                               ? tr("step: %1 s so far").arg(stepSeconds, 0, 'f', 1)
                               : tr("%1 ms/step").arg(costs.join(QStringLiteral(" | "))));
}

void MainWindow::updateTitle() {
  QString title = tr("FooBall — %1 — %2").arg(sourceName_, runs_->backendName(0));
  if (runs_->comparing()) title += tr(" vs %1").arg(runs_->backendName(1));
  setWindowTitle(title);
}

void MainWindow::openSceneDialog() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), QString(),
                                                    tr("FooBall scenes (*.json);;All files (*)"));
  if (!path.isEmpty()) openSceneFile(path);
}

void MainWindow::saveSceneDialog() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Save scene"), QString(),
                                                    tr("FooBall scenes (*.json)"));
  if (!path.isEmpty()) saveSceneFile(path);
}

void MainWindow::exportChartsPng() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Export charts as PNG"), QString(),
                                                    tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (charts_->exportPng(path)) {
    showStatus(tr("Charts saved to %1").arg(path));
  } else {
    reportError_(tr("Could not export the charts"), tr("Could not write %1").arg(path));
  }
}

void MainWindow::exportChartsCsv() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Export charts as CSV"), QString(),
                                                    tr("CSV files (*.csv)"));
  if (path.isEmpty()) return;
  if (charts_->exportCsv(path)) {
    showStatus(tr("Chart data saved to %1").arg(path));
  } else {
    reportError_(tr("Could not export the chart data"), tr("Could not write %1").arg(path));
  }
}

void MainWindow::openBenchmark() {
  if (!benchmark_) {
    benchmark_ = new BenchmarkDialog(this);
    // The measurements and the simulation would share the CPU: the runs pause meanwhile.
    connect(benchmark_, &BenchmarkDialog::runStarted, this, [this] {
      pausedForBenchmark_ = !runs_->paused();
      if (pausedForBenchmark_) runs_->setPaused(true);
      showStatus(tr("Paused while the benchmark runs"));
    });
    connect(benchmark_, &BenchmarkDialog::runFinished, this, [this] {
      if (pausedForBenchmark_) runs_->setPaused(false);
      pausedForBenchmark_ = false;
    });
  }
  benchmark_->show();
  benchmark_->raise();
  benchmark_->activateWindow();
}

void MainWindow::readSettings() {
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  docksSized_ = restoreState(settings.value("window/state").toByteArray());
  temperatureAction_->setChecked(settings.value("drawing/temperature", false).toBool());
  tethersAction_->setChecked(settings.value("drawing/tethers", true).toBool());
  velocityVectorsAction_->setChecked(settings.value("drawing/velocityVectors", false).toBool());
  centreOfMassAction_->setChecked(settings.value("drawing/centreOfMass", false).toBool());
  const bool sideBySide = settings.value("drawing/sideBySide", false).toBool();
  (sideBySide ? sideBySideAction_ : overlayAction_)->trigger();
  runs_->setMouseMode(static_cast<MouseMode>(
      std::clamp(settings.value("mouse/mode", 0).toInt(), 0, int(MouseMode::Slingshot))));
  runs_->setScope(static_cast<Scope>(
      std::clamp(settings.value("mouse/scope", 0).toInt(), 0, int(Scope::Selected))));
  runs_->setStrength(std::max(0.0, settings.value("mouse/strength", kDefaultStrength).toDouble()));
  timeScale_ = std::clamp(settings.value("time/scale", kDefaultTimeScale).toDouble(), 0.05, 8.0);
}

void MainWindow::writeSettings() const {
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  settings.setValue("drawing/temperature", view_->temperatureColouring());
  settings.setValue("drawing/tethers", view_->tethers());
  settings.setValue("drawing/velocityVectors", view_->velocityVectors());
  settings.setValue("drawing/centreOfMass", view_->centreOfMass());
  settings.setValue("drawing/sideBySide", view_->compareLayout() == CompareLayout::SideBySide);
  settings.setValue("mouse/mode", int(runs_->interactions().mode));
  settings.setValue("mouse/scope", int(runs_->interactions().scope));
  settings.setValue("mouse/strength", runs_->interactions().strength);
  settings.setValue("time/scale", timeScale_);
  settings.setValue("run/backend", runs_->backendName(0));
  if (!presetName_.isEmpty()) settings.setValue("scene/preset", presetName_);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (docksSized_) return;
  docksSized_ = true;
  // Once the window has its size: the view gets most of it, the charts a strip below (as
  // small as they go), the settings a column.
  QMetaObject::invokeMethod(
      this,
      [this] {
        resizeDocks({chartsDock_}, {1}, Qt::Vertical);
        resizeDocks({sidebarDock_}, {kSidebarWidth}, Qt::Horizontal);
      },
      Qt::QueuedConnection);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (rememberSettings_) writeSettings();
  if (benchmark_) benchmark_->close();  // cancels a run: the app quits with its main window
  event->accept();
}

}  // namespace fooball::gui
