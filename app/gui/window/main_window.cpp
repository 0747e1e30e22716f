#include "window/main_window.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QResizeEvent>
#include <QShowEvent>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include "charts/chart_panel.h"
#include "control/ball_commands.h"
#include "control/mouse_tools.h"
#include "control/run_events.h"
#include "control/scene_commands.h"
#include "control/scene_session.h"
#include "control/sidebar_controller.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "readouts/compare_readout.h"
#include "readouts/statistics_panel.h"
#include "readouts/status_panel.h"
#include "readouts/timeline_bar.h"
#include "run/run_controller.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/fitted_scroll_area.h"
#include "widgets/number_field_keys.h"
#include "widgets/strip_scroll_area.h"
#include "widgets/user_messages.h"
#include "widgets/wheel_needs_focus.h"
#include "window/dock_layout.h"
#include "window/window_actions.h"

namespace fooball::gui {

namespace {

constexpr QSize kDefaultWindowSize{1440, 900};  // px, before it is fitted to the screen

}  // namespace

MainWindow::MainWindow(const StartupOptions& options, QWidget* parent)
    : QMainWindow(parent),
      runs_(std::make_unique<RunController>(options.scene, options.runs)),
      rememberSettings_(options.rememberSettings) {
  setObjectName(QStringLiteral("mainWindow"));
  view_ = new SimulationView(*runs_);
  compareReadout_ = new CompareReadout;
  auto* central = new QWidget;
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(new StripScrollArea(compareReadout_));
  layout->addWidget(view_, 1);
  setCentralWidget(central);

  createDocks();
  defaultLayout_ = saveState();
  auto* undoStack = new QUndoStack(this);
  feed_ = std::make_unique<RunFeed>(
      *runs_, RunFeed::Targets{*charts_, *compareReadout_, *sidebar_, *sidebarDock_, *statistics_});
  frames_ = new FrameLoop(*runs_, *view_, *feed_, this);
  messages_ = new UserMessages(*statusBar(), *this);
  session_ = new SceneSession({*runs_, *view_, *sidebar_, *feed_, *frames_, *undoStack},
                              options.presetName, options.sourceName, this);
  scenes_ = std::make_unique<SceneCommands>(
      SceneCommands::Parts{*session_, *runs_, *sidebar_, *feed_, *undoStack, *messages_});
  balls_ = std::make_unique<BallCommands>(
      BallCommands::Parts{*runs_, *feed_, *undoStack, *sidebar_->inspector(), *messages_});
  actions_ = new WindowActions({*this, *runs_, *view_, *sidebar_, *charts_, *feed_, *session_,
                                *scenes_, *balls_, *undoStack, *messages_, *sidebarDock_,
                                *chartsDock_, *statisticsDock_, recordingTarget()});
  new NumberFieldKeys(*this, *view_);  // Space and '.' reach the actions from a number field
  status_ = new StatusPanel(*statusBar(), *runs_, frames_->frameRate());
  // In the status bar's stretch, not under the box: the box keeps every pixel of height.
  timeline_ = new TimelineBar(*runs_);
  statusBar()->addWidget(timeline_, 1);
  new SidebarController(
      {*sidebar_, *runs_, *session_, *scenes_, *balls_, *feed_, *frames_, *view_, *messages_},
      this);
  new MouseTools({*view_, *runs_, *feed_, *sidebar_, *status_, *messages_}, this);
  connectParts();

  resize(kDefaultWindowSize);
  if (rememberSettings_) docksSized_ = readWindowSettings(remembered());
  if (options.balls) runs_->setBallCount(*options.balls);
  // Compare mode shows the chaos baseline unless the user hides it.
  if (options.runs.size() > 1) runs_->setBaseline(true);
  for (const Vec2 point : options.attractors)
    runs_->changeTools([&](RunGroup& group) { group.addAttractor(point); });
  actions_->applyShowOptions(options.show);

  session_->syncSidebar();
  session_->restartCharts();
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
  // As narrow as the sidebar's controls allow, so the box keeps the room at 1000 px wide.
  sidebarScroll_ = new FittedScrollArea(sidebar_);
  new WheelNeedsFocus(*sidebarScroll_);
  sidebarDock_ = new QDockWidget(tr("Settings"), this);
  sidebarDock_->setObjectName(QStringLiteral("settingsDock"));
  sidebarDock_->setWidget(sidebarScroll_);
  addDockWidget(Qt::RightDockWidgetArea, sidebarDock_);

  // The charts beside the box, not under it: a readable chart needs more height than the box
  // can spare, and a column of them fits as many whole charts as its height allows.
  charts_ = new ChartPanel;
  chartsDock_ = new QDockWidget(tr("Charts"), this);
  chartsDock_->setObjectName(QStringLiteral("chartsDock"));
  chartsDock_->setWidget(charts_);
  // In front of the settings at first, the least width a window needs (1000 px);
  // giveDocksFirstShare gives them a column of their own on a wide window.
  tabifyDockWidget(sidebarDock_, chartsDock_);

  // The statistics take the charts' place as a tab when opened: the box keeps its room.
  statistics_ = new StatisticsPanel;
  statisticsDock_ = new QDockWidget(tr("Statistics"), this);
  statisticsDock_->setObjectName(QStringLiteral("statisticsDock"));
  statisticsDock_->setWidget(statistics_);
  // Under the box while closed: in the settings' area even a closed dock widens the window.
  addDockWidget(Qt::BottomDockWidgetArea, statisticsDock_);
  statisticsDock_->hide();
  tabWithChartsWhenOpened(*this, *statisticsDock_, *chartsDock_);
  // Shown, or brought to the front of its tabs: measure at once rather than at the next refresh.
  connect(statisticsDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (visible) {
      QMetaObject::invokeMethod(
          this, [this] { feed_->showStatistics(); }, Qt::QueuedConnection);
    }
  });
}

void MainWindow::connectParts() {
  new RunEvents({*runs_, *feed_, *view_, *sidebar_, *frames_, *session_, *messages_}, this);
  RunController* runs = runs_.get();
  connect(runs, &RunController::pausedChanged, actions_, &WindowActions::showPaused);
  connect(runs, &RunController::pausedChanged, timeline_, &TimelineBar::showHistory);
  connect(runs, &RunController::selectionChanged, this, [this](std::optional<std::size_t> index) {
    actions_->deleteBall()->setEnabled(index.has_value());
    if (index) sidebarScroll_->ensureWidgetVisible(sidebar_->inspector());
  });
  const auto showRunNames = [this] {
    updateTitle();
    updateStatusBar();
  };
  connect(runs, &RunController::runsChanged, this, showRunNames);
  connect(runs, &RunController::optionsChanged, this, showRunNames);
  connect(runs, &RunController::rewound, this, &MainWindow::updateStatusBar);
  connect(session_, &SceneSession::sceneLoaded, this, &MainWindow::updateTitle);
  connect(actions_, &WindowActions::stepped, this, &MainWindow::updateStatusBar);
  connect(actions_, &WindowActions::resetLayoutRequested, this, &MainWindow::resetLayout);
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
  setWindowTitle(tr("%1 — %2").arg(session_->sourceName(), runs_->labels().join(tr(" vs "))));
}

RecordingTarget MainWindow::recordingTarget() const {
  return {*view_, *charts_, *chartsDock_, *frames_, *runs_};
}

RememberedParts MainWindow::remembered() {
  return {*this, *actions_, *view_, *runs_, *frames_, *session_};
}

void MainWindow::resetLayout() {
  showNormal();
  // Out of its tab group first: restoreState() would leave a shell of the group behind, in
  // which the reopened dock could not be raised.
  removeDockWidget(statisticsDock_);
  restoreState(defaultLayout_);
  resize(kDefaultWindowSize);
  keepFullyOnScreen(*this);
  giveDocksFirstShare(*this, *chartsDock_, *sidebarDock_);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  if (docksSized_ && event->oldSize().isValid() && event->oldSize().width() != width())
    followWindowWidth(*this, *chartsDock_, *sidebarDock_);
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
  giveDocksFirstShare(*this, *chartsDock_, *sidebarDock_);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (rememberSettings_) writeWindowSettings(remembered());
  actions_->closeTools();  // cancels their runs: the app quits with its main window
  event->accept();
}

}  // namespace fooball::gui
