#include "frames/run_feed.h"

#include <QWidget>
#include <vector>

#include "charts/chart_panel.h"
#include "readouts/compare_readout.h"
#include "readouts/run_counters.h"
#include "readouts/statistics_panel.h"
#include "run/run_controller.h"
#include "sidebar/settings_sidebar.h"

namespace fooball::gui {

namespace {

/// Changes of one setting closer together than this (ms) are one gesture: a slider's drag sends
/// one every few ms, a user's separate changes are seconds apart.
constexpr qint64 kGestureGapMs = 700;

}  // namespace

RunFeed::RunFeed(const RunController& runs, Targets targets) : runs_(runs), to_(targets) {}

void RunFeed::sampleCharts() {
  // No chart plots the overlap or the escaped count: the counters table computes them.
  const RunGroup& group = runs_.group();
  for (std::size_t i = 0; i < group.runCount(); ++i) {
    to_.charts.addSample(int(i), group.run(i).metrics(GeometryChecks::Skip), group.divergence(i));
  }
  if (const Simulation* baseline = group.baseline()) {
    to_.charts.addBaselineSample(baseline->metrics(GeometryChecks::Skip),
                                 *group.baselineDivergence());
  }
}

void RunFeed::showReadouts() {
  const RunGroup& group = runs_.group();
  if (!to_.compareReadout.isHidden()) to_.compareReadout.showDivergences(group.divergences());
  // The deepest-overlap search is O(N log N): only for a table someone can see.
  RunCounters* counters = to_.sidebar.counters();
  if (!to_.sidebarDock.isHidden() && counters->isVisible()) {
    std::vector<Metrics> metrics;
    for (std::size_t i = 0; i < group.runCount(); ++i)
      metrics.push_back(group.run(i).metrics());
    counters->showMetrics(metrics);
  }
}

void RunFeed::showSelectedBall() {
  const auto selected = runs_.group().selected();
  to_.sidebar.showSelection(selected, selected ? runs_.group().ball(*selected) : BallDef{});
}

void RunFeed::showStatistics() {
  to_.statistics.refresh(runs_.group());
}

void RunFeed::showRuns() {
  to_.compareReadout.setVisible(runs_.comparing() || runs_.group().hasBaseline());
  to_.compareReadout.showRuns(runs_.labels(), runs_.group().hasBaseline());
  to_.sidebar.counters()->showRuns(runs_.labels());
  to_.statistics.showRuns(runs_.labels());
  showReadouts();
}

void RunFeed::addRun() {
  to_.charts.addRun(runs_.labels().back());
  to_.charts.setBaselineShown(runs_.group().hasBaseline());
  sampleCharts();
}

void RunFeed::removeRun(int index) {
  to_.charts.removeRun(index);
}

void RunFeed::renameRun(int index) {
  to_.charts.renameRun(index, runs_.label(index));
}

void RunFeed::showLabels() {
  to_.compareReadout.showRuns(runs_.labels(), runs_.group().hasBaseline());
}

void RunFeed::showBaseline(bool on) {
  to_.charts.setBaselineShown(on);
  sampleCharts();
}

void RunFeed::restart() {
  to_.charts.reset(runs_.labels());
  to_.charts.setBaselineShown(runs_.group().hasBaseline());
  sampleCharts();
  to_.statistics.restart();
  showStatistics();
}

void RunFeed::dropAfter(double time) {
  to_.charts.dropAfter(time);
  sampleCharts();
}

void RunFeed::markChange(const QString& label, const QString& gesture) {
  const bool continues = !gesture.isEmpty() && gesture == lastGesture_ && gestureClock_.isValid() &&
                         gestureClock_.elapsed() < kGestureGapMs;
  if (continues) {
    to_.charts.replaceNewestMarker(runs_.group().time(), label);
  } else {
    to_.charts.addMarker(runs_.group().time(), label);
  }
  lastGesture_ = gesture;
  gestureClock_.start();
}

void RunFeed::markAt(double time, const QString& label) {
  to_.charts.addMarker(time, label);
}

}  // namespace fooball::gui
