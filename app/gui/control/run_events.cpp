#include "control/run_events.h"

#include <QList>

#include "control/scene_session.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "run/run_controller.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/user_messages.h"

namespace fooball::gui {

RunEvents::RunEvents(Parts parts, QObject* parent) : QObject(parent), parts_(parts) {
  RunController* runs = &parts_.runs;
  RunFeed& feed = parts_.feed;
  SimulationView* view = &parts_.view;
  connect(runs, &RunController::pausedChanged, this, [this, &feed, view](bool paused) {
    parts_.frames.restartClock();
    view->update();
    // The readouts show the state paused on, not the one of their last refresh, frames before.
    if (paused) {
      feed.showReadouts();
      feed.showSelectedBall();
    }
  });
  connect(runs, &RunController::selectionChanged, this, [&feed, view] {
    feed.showSelectedBall();
    view->update();
  });
  connect(runs, &RunController::ballsChanged, this, [this, &feed, view] {
    parts_.sidebar.showBallCount(parts_.runs.group().ballCount());
    feed.showSelectedBall();
    feed.showReadouts();
    view->update();
  });
  connect(runs, &RunController::runsChanged, this, [this, view] {
    parts_.session.showRuns();
    view->update();
  });
  connect(runs, &RunController::optionsChanged, this, [&feed](int index) {
    feed.renameRun(index);
    feed.showLabels();
  });
  connect(runs, &RunController::rewound, this, [&feed, view](double time) {
    feed.dropAfter(time);  // the charts end where the runs are now
    feed.showReadouts();
    feed.showSelectedBall();
    view->update();
  });
  connectFailures();
}

void RunEvents::connectFailures() {
  RunController* runs = &parts_.runs;
  connect(runs, &RunController::runsFailed, this,
          [this](const QString&, const QList<int>& removed) {
            for (const int index : removed)
              parts_.feed.removeRun(index);
            parts_.feed.markAt(parts_.runs.group().time(), tr("a run stopped"));
          });
  // Queued: the message box's own event loop must not run inside the frame that collected the
  // failed step.
  connect(
      runs, &RunController::runsFailed, this,
      [this](const QString& lines) { parts_.messages.reportError(tr("A run stopped"), lines); },
      Qt::QueuedConnection);
  connect(runs, &RunController::runsRestarted, this, [this](double time) {
    parts_.feed.markAt(time, tr("runs restarted identical"));
    parts_.messages.showStatus(tr("Every run restarted from run 0's state at t = %1 s, so that "
                                  "all start identical; the charts keep their history")
                                   .arg(time, 0, 'f', 2));
  });
}

}  // namespace fooball::gui
