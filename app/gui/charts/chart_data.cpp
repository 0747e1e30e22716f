#include "chart_data.h"

#include <algorithm>

namespace fooball::gui {

void ChartData::reset(const QStringList& runNames) {
  runNames_ = runNames.mid(0, kMaxRuns);
  if (runNames_.isEmpty()) runNames_.append(QString());
  for (Run& run : runs_)
    run.history.clear();
  markers_.clear();
}

void ChartData::addSample(int runIndex, const Metrics& metrics) {
  if (runIndex < 0 || runIndex >= runCount()) return;
  Run& run = runs_[runIndex];
  // The history starts over on an empty history or a time going back (see SampleHistory::add);
  // E₀ starts over with it.
  if (run.history.empty() || metrics.time < run.history.latest().time) {
    run.initialTotalEnergy = metrics.sums.totalEnergy();
  }
  run.history.add(chartSampleFrom(metrics, run.initialTotalEnergy));
}

void ChartData::addMarker(double time, const QString& label) {
  markers_.push_back({time, label});
  if (markers_.size() > kMaxMarkers) markers_.pop_front();
}

bool ChartData::hasSamples() const {
  return std::any_of(runs_.begin(), runs_.begin() + runCount(),
                     [](const Run& run) { return !run.history.empty(); });
}

double ChartData::startTime() const {
  bool found = false;
  double start = 0.0;
  for (int i = 0; i < runCount(); ++i) {
    if (runs_[i].history.empty()) continue;
    start = found ? std::min(start, runs_[i].history.first().time) : runs_[i].history.first().time;
    found = true;
  }
  return start;
}

double ChartData::endTime() const {
  bool found = false;
  double end = 0.0;
  for (int i = 0; i < runCount(); ++i) {
    if (runs_[i].history.empty()) continue;
    end = found ? std::max(end, runs_[i].history.latest().time) : runs_[i].history.latest().time;
    found = true;
  }
  return end;
}

}  // namespace fooball::gui
