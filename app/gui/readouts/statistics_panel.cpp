#include "readouts/statistics_panel.h"

#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <vector>

#include "charts/speed_histogram_chart.h"
#include "fooball/run_group.h"
#include "readouts/gas_readout.h"

namespace fooball::gui {

namespace {

/// Tick intervals on the speed axis.
constexpr int kSpeedTicks = 5;
/// m/s the speed axis spans while no ball moves.
constexpr double kRestingRange = 1.0;
/// px: narrower, the histogram's axis labels crowd.
constexpr int kMinHistogramWidth = 260;
/// The share of the panel's height the table takes at most; taller, it scrolls (the histogram
/// above keeps a readable plot in the charts' column at 1000×650).
constexpr double kMaxTableShare = 0.45;

/// Bins that split every tick interval of `scale` alike, into 1, 2, 4, 5 or 10, so that bin
/// edges fall on round speeds: as close to `wanted` as that allows.
std::size_t alignedBins(const AxisScale& scale, std::size_t wanted) {
  const auto ticks = static_cast<std::size_t>(
      std::max(1.0, std::round((scale.max - scale.min) / scale.tickInterval)));
  const auto distance = [wanted](std::size_t bins) {
    return bins > wanted ? bins - wanted : wanted - bins;
  };
  std::size_t best = ticks;
  for (const std::size_t split : {2u, 4u, 5u, 10u}) {
    if (distance(ticks * split) < distance(best)) best = ticks * split;
  }
  return best;
}

}  // namespace

StatisticsPanel::StatisticsPanel(QWidget* parent)
    : QWidget(parent), histogram_(new SpeedHistogramChart), readout_(new GasReadout) {
  setObjectName(QStringLiteral("statisticsPanel"));
  histogram_->setMinimumWidth(kMinHistogramWidth);
  // The table scrolls rather than make the dock taller or wider than the window allows: eight
  // runs' columns are wider than the charts' column.
  tableScroll_ = new QScrollArea;
  tableScroll_->setWidget(readout_);
  tableScroll_->setWidgetResizable(true);
  tableScroll_->setFrameShape(QFrame::NoFrame);
  // The histogram above its table: the statistics share the charts' column beside the box.
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(histogram_, 1);
  layout->addWidget(tableScroll_, 0);
  showRuns({});
}

void StatisticsPanel::showRuns(const QStringList& labels) {
  if (runsShown_ && labels == labels_) return;
  runsShown_ = true;
  labels_ = labels;
  monitor_.clear();
  histogram_->setRuns(labels, labels.size() > 1 ? tr("2D Maxwell–Boltzmann at run 0's kT")
                                                : tr("2D Maxwell–Boltzmann at this kT"));
  readout_->showRuns(labels);
  fitTableHeight();
}

void StatisticsPanel::hideEvent(QHideEvent* event) {
  QWidget::hideEvent(event);
  // Closed, the panel still counts in its dock area's least size: it must not hold the window.
  tableScroll_->setMinimumHeight(0);
}

void StatisticsPanel::fitTableHeight() {
  // A scroll area asks for little room of its own: give it the table's height, up to a share,
  // while it is on screen (see hideEvent).
  if (!onScreen()) return;
  const int scrollBar = tableScroll_->horizontalScrollBar()->sizeHint().height();
  tableScroll_->setMinimumHeight(
      std::min(readout_->sizeHint().height() + scrollBar, int(kMaxTableShare * height())));
}

void StatisticsPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  fitTableHeight();
}

void StatisticsPanel::restart() {
  monitor_.clear();
  speedScale_.reset();
}

bool StatisticsPanel::onScreen() const {
  // A dock behind another's tab stays "visible" to Qt, moved out of its window's sight.
  // (visibleRegion() will not tell: the chart and the table cover the panel, so it is empty.)
  return isVisible() && window()->rect().intersects(QRect(mapTo(window(), QPoint()), size()));
}

void StatisticsPanel::refresh(const RunGroup& group) {
  if (!onScreen()) return;
  double fastest = 0.0;  // m/s
  for (std::size_t i = 0; i < group.runCount(); ++i)
    fastest = std::max(fastest, speedToShow(group.run(i)));
  ValueRange speeds;
  speeds.include(0.0);
  speeds.include(fastest > 0.0 ? fastest : kRestingRange);
  speedScale_ = followValues(speeds, speedScale_, kSpeedTicks);

  const std::size_t bins = alignedBins(*speedScale_, speedBins(group.ballCount()));
  const GasMonitor::Snapshot& snapshot = monitor_.measure(group, bins, speedScale_->max);
  std::vector<const SpeedHistogram*> histograms;
  for (const RunGasStatistics& run : snapshot.runs)
    histograms.push_back(&run.histogram);
  histogram_->draw(histograms, snapshot.expectedCounts, *speedScale_);
  readout_->showStatistics(snapshot);
  fitTableHeight();
  ++refreshes_;
}

}  // namespace fooball::gui
