#include "window/main_window.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QMessageBox>
#include <QResizeEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QShowEvent>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "charts/chart_panel.h"
#include "fooball/presets.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "readouts/compare_readout.h"
#include "readouts/statistics_panel.h"
#include "readouts/status_panel.h"
#include "readouts/timeline_bar.h"
#include "run/run_controller.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/number_field_keys.h"
#include "window/sidebar_wiring.h"
#include "window/window_actions.h"
#include "window/window_settings.h"

namespace fooball::gui {

namespace {

constexpr int kStatusMessageMs = 8000;
constexpr int kSidebarWidth = 300;        // px
constexpr QSize kDefaultSize{1440, 900};  // px, before it is fitted to the screen
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

MainWindow::MainWindow(const StartupOptions& options, QWidget* parent)
    : QMainWindow(parent),
      runs_(std::make_unique<RunController>(options.scene, options.runs)),
      rememberSettings_(options.rememberSettings),
      presetName_(options.presetName),
      sourceName_(options.sourceName) {
  setObjectName(QStringLiteral("mainWindow"));
  reportError_ = [this](const QString& title, const QString& message) {
    QMessageBox::warning(this, title, message);
  };

  view_ = new SimulationView(*runs_);
  compareReadout_ = new CompareReadout;
  auto* central = new QWidget;
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(compareReadout_);
  layout->addWidget(view_, 1);
  setCentralWidget(central);

  createDocks();
  defaultLayout_ = saveState();
  undoStack_ = new QUndoStack(this);
  feed_ = std::make_unique<RunFeed>(
      *runs_, RunFeed::Targets{*charts_, *compareReadout_, *sidebar_, *sidebarDock_, *statistics_});
  frames_ = new FrameLoop(*runs_, *view_, *feed_, this);
  actions_ = new WindowActions(*this);
  new NumberFieldKeys(*this, *view_);  // Space and '.' reach the actions from a number field
  status_ = new StatusPanel(*statusBar(), *runs_, frames_->frameRate());
  // In the status bar's stretch, not under the box: the box keeps every pixel of height.
  timeline_ = new TimelineBar(*runs_);
  statusBar()->addWidget(timeline_, 1);
  wireSidebar(*this);
  wireView(*this);
  connectRuns();

  resize(kDefaultSize);
  if (rememberSettings_) docksSized_ = readWindowSettings(*this);
  if (options.balls) runs_->setBallCount(*options.balls);
  // Compare mode shows the chaos baseline unless the user hides it.
  if (options.runs.size() > 1) runs_->setBaseline(true);
  for (const Vec2 point : options.attractors)
    runs_->changeTools([&](RunGroup& group) { group.addAttractor(point); });
  actions_->applyShowOptions(options.show);

  view_->setPreset(findPreset(presetName_.toStdString()));
  syncSidebar();
  resetCharts();
  updateTitle();
  updateStatusBar();
}

MainWindow::~MainWindow() {
  // The widgets go first: they refer to the runs, and a field losing focus as it is destroyed
  // still reports an edit. The Tools' dialogs first of all: they stop and join their threads.
  actions_->destroyTools();
  delete sidebarDock_;
  delete chartsDock_;
  delete statisticsDock_;
  delete takeCentralWidget();
}

void MainWindow::createDocks() {
  sidebar_ = new SettingsSidebar;
  sidebarScroll_ = new QScrollArea;
  sidebarScroll_->setWidget(sidebar_);
  sidebarScroll_->setWidgetResizable(true);
  sidebarScroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  fitSidebarWidth();
  sidebar_->installEventFilter(this);
  sidebarDock_ = new QDockWidget(tr("Settings"), this);
  sidebarDock_->setObjectName(QStringLiteral("settingsDock"));
  sidebarDock_->setWidget(sidebarScroll_);
  addDockWidget(Qt::RightDockWidgetArea, sidebarDock_);

  charts_ = new ChartPanel;
  chartsDock_ = new QDockWidget(tr("Charts"), this);
  chartsDock_->setObjectName(QStringLiteral("chartsDock"));
  chartsDock_->setWidget(charts_);
  addDockWidget(Qt::BottomDockWidgetArea, chartsDock_);
  // The charts run the full width under the box and the settings: a wide strip fits four charts
  // side by side, and the settings column, which scrolls anyway, leaves the box the height.
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);

  // The statistics take the charts' place as a tab when opened: the box keeps its room, and the
  // wide strip fits the histogram beside its table.
  statistics_ = new StatisticsPanel;
  statisticsDock_ = new QDockWidget(tr("Statistics"), this);
  statisticsDock_->setObjectName(QStringLiteral("statisticsDock"));
  statisticsDock_->setWidget(statistics_);
  addDockWidget(Qt::BottomDockWidgetArea, statisticsDock_);
  statisticsDock_->hide();
  // Tabbed when opened, not before: a saved layout with a tab group holding a closed dock comes
  // back wider than the window's least width (868 px against 505 on an 800 px test screen).
  // Where the user has moved it, it stays.
  connect(statisticsDock_->toggleViewAction(), &QAction::toggled, this, [this](bool open) {
    if (!open) return;
    if (dockWidgetArea(statisticsDock_) == Qt::BottomDockWidgetArea &&
        !statisticsDock_->isFloating() && !chartsDock_->isHidden() &&
        !tabifiedDockWidgets(statisticsDock_).contains(chartsDock_)) {
      tabifyDockWidget(chartsDock_, statisticsDock_);
    }
    // To the front of its tabs once the layout has run: before, a dock just shown or in a window
    // not shown yet has no tab to raise.
    QTimer::singleShot(0, statisticsDock_, &QDockWidget::raise);
  });
  // Shown, or brought to the front of its tabs: measure at once rather than at the next refresh.
  connect(statisticsDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (visible) {
      QMetaObject::invokeMethod(
          this, [this] { feed_->showStatistics(); }, Qt::QueuedConnection);
    }
  });
}

void MainWindow::connectRuns() {
  connect(runs_.get(), &RunController::pausedChanged, this, [this](bool paused) {
    actions_->showPaused(paused);
    timeline_->showHistory();
    frames_->restartClock();
    view_->update();
    // The readouts show the state paused on, not the one of their last refresh, frames before.
    if (paused) {
      feed_->showReadouts();
      feed_->showSelectedBall();
    }
  });
  connect(runs_.get(), &RunController::selectionChanged, this,
          [this](std::optional<std::size_t> index) {
            actions_->deleteBall()->setEnabled(index.has_value());
            feed_->showSelectedBall();
            if (index) sidebarScroll_->ensureWidgetVisible(sidebar_->inspector());
            view_->update();
          });
  connect(runs_.get(), &RunController::ballsChanged, this, [this] {
    sidebar_->showBallCount(runs_->group().ballCount());
    feed_->showSelectedBall();
    feed_->showReadouts();
    view_->update();
  });
  connect(runs_.get(), &RunController::runsChanged, this, [this] {
    showRuns();
    updateTitle();
    updateStatusBar();
    view_->update();
  });
  connect(runs_.get(), &RunController::optionsChanged, this, [this](int index) {
    feed_->renameRun(index);
    feed_->showLabels();
    updateTitle();
    updateStatusBar();
  });
  connect(runs_.get(), &RunController::rewound, this, [this](double time) {
    feed_->dropAfter(time);  // the charts end where the runs are now
    feed_->showReadouts();
    feed_->showSelectedBall();
    updateStatusBar();
    view_->update();
  });
  connect(runs_.get(), &RunController::runsFailed, this,
          [this](const QString&, const QList<int>& removed) {
            for (const int index : removed)
              feed_->removeRun(index);
            feed_->markAt(runs_->group().time(), tr("a run stopped"));
          });
  // Queued: the message box's own event loop must not run inside the frame that collected the
  // failed step.
  connect(
      runs_.get(), &RunController::runsFailed, this,
      [this](const QString& lines) { reportError_(tr("A run stopped"), lines); },
      Qt::QueuedConnection);
  connect(runs_.get(), &RunController::runsRestarted, this, [this](double time) {
    feed_->markAt(time, tr("runs restarted identical"));
    showStatus(tr("Every run restarted from run 0's state at t = %1 s, so that all start "
                  "identical; the charts keep their history")
                   .arg(time, 0, 'f', 2));
  });
}

void MainWindow::fitSidebarWidth() {
  // As narrow as the sidebar's controls allow, so the box keeps the room at 1000 px wide; and
  // never narrower, or the rightmost column (the counters', a run's remove button) is cut off.
  // Its controls change with the runs, so this follows them (eventFilter).
  sidebarScroll_->setMinimumWidth(sidebar_->minimumSizeHint().width() +
                                  sidebarScroll_->verticalScrollBar()->sizeHint().width() +
                                  2 * sidebarScroll_->frameWidth());
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  // The sidebar's rows change with the runs and their options, laid out in a posted event.
  if (watched == sidebar_ && event->type() == QEvent::LayoutRequest) fitSidebarWidth();
  return QMainWindow::eventFilter(watched, event);
}

void MainWindow::showRuns() {
  sidebar_->runList()->showRuns(runs_->group());
  feed_->showRuns();
}

void MainWindow::syncSidebar() {
  const RunGroup& group = runs_->group();
  sidebar_->showSceneSource(presetName_, sourceName_);
  sidebar_->showBallCount(group.ballCount());
  sidebar_->showWorld(group.world());
  sidebar_->showStrength(group.interactions().strength);
  sidebar_->showTimeScale(frames_->timeScale());
  sidebar_->showMouseMode(group.interactions().mode);
  sidebar_->showScope(group.interactions().scope);
  sidebar_->showAttractorCount(group.interactions().attractors().size());
  sidebar_->showDrawing(view_->temperatureColouring(), view_->tethers(), view_->velocityVectors(),
                        view_->centreOfMass());
  sidebar_->runList()->showCompareLayout(view_->compareLayout());
  showRuns();
  feed_->showSelectedBall();
}

void MainWindow::resetCharts() {
  frames_->restartSampling();
  feed_->restart();
}

void MainWindow::showStatus(const QString& message) {
  statusBar()->showMessage(message, kStatusMessageMs);
}

void MainWindow::loadScene(const Scene& scene, const QString& presetName,
                           const QString& sourceName) {
  presetName_ = presetName;
  sourceName_ = sourceName;
  runs_->loadScene(scene);
  view_->setPreset(findPreset(presetName_.toStdString()));
  undoStack_->clear();  // other balls (undoStack())
  syncSidebar();
  resetCharts();
  updateTitle();
}

void MainWindow::restart() {
  runs_->restart();
  undoStack_->clear();  // the balls as loaded (undoStack())
  resetCharts();
}

void MainWindow::resetScene() {
  runs_->loadScene(runs_->group().loadedScene());
  undoStack_->clear();  // the balls as loaded (undoStack())
  resetSliders(*this);
  syncSidebar();
  resetCharts();
}

void MainWindow::advanceFrame(double elapsedSeconds) {
  frames_->advance(elapsedSeconds);
}

void MainWindow::startLiveUpdates() {
  frames_->start();
  status_->start();
}

void MainWindow::updateStatusBar() {
  status_->update();
  timeline_->showHistory();
}

void MainWindow::updateTitle() {
  // Qt adds the application's display name, "FooBall", after it.
  setWindowTitle(tr("%1 — %2").arg(sourceName_, runs_->labels().join(tr(" vs "))));
}

void MainWindow::resetLayout() {
  showNormal();
  // Out of its tab group first: restoreState() would leave a shell of the group behind, in
  // which the reopened dock could not be raised.
  removeDockWidget(statisticsDock_);
  restoreState(defaultLayout_);
  resize(kDefaultSize);
  keepFullyOnScreen(*this);
  sizeDocks();
}

void MainWindow::sizeDocks() {
  // Once the window has its size: the view gets most of it, the charts a strip below (they
  // scroll when there are more than fit), the settings a column.
  QMetaObject::invokeMethod(
      this,
      [this] {
        resizeDocks({chartsDock_}, {firstChartsHeight(height())}, Qt::Vertical);
        resizeDocks({sidebarDock_}, {kSidebarWidth}, Qt::Horizontal);
      },
      Qt::QueuedConnection);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  // The dock keeps its height in pixels when the window changes, so shrinking a tall window
  // would leave the box a sliver above the charts: keep the charts' share of the height instead
  // (the share the user dragged them to, or the first one).
  const QSize old = event->oldSize();
  if (!docksSized_ || !old.isValid() || old.height() == height() || chartsDock_->isHidden() ||
      chartsDock_->isFloating()) {
    return;
  }
  const double share = double(chartsDock_->height()) / double(old.height());
  QMetaObject::invokeMethod(
      this,
      [this, share] {
        resizeDocks({chartsDock_}, {int(std::lround(share * height()))}, Qt::Vertical);
      },
      Qt::QueuedConnection);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (!shownOnce_ && rememberSettings_) {
    // Only now does the window have a frame: fit it again, frame included.
    QMetaObject::invokeMethod(
        this, [this] { keepFullyOnScreen(*this); }, Qt::QueuedConnection);
  }
  shownOnce_ = true;
  if (docksSized_) return;
  docksSized_ = true;
  sizeDocks();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (rememberSettings_) writeWindowSettings(*this);
  actions_->closeTools();  // cancels their runs: the app quits with its main window
  event->accept();
}

}  // namespace fooball::gui
