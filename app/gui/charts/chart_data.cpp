#include "chart_data.h"

#include <algorithm>

namespace fooball::gui {

ChartData::ChartData() {
  runs_.reserve(kMaxRuns);
  baseline_.name = QStringLiteral("baseline");
  reset({});
}

void ChartData::reset(const QStringList& runNames) {
  QStringList names = runNames.mid(0, kMaxRuns);
  if (names.isEmpty()) names.append(QString());
  // The histories are cleared, not made anew: a new one allocates and zeroes its recent ring
  // (8'192 samples, 0.7 MB), which every restart of eight runs did eight times.
  runs_.resize(static_cast<std::size_t>(names.size()));
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    runs_[i].name = names[static_cast<qsizetype>(i)];
    runs_[i].history.clear();
  }
  baseline_.history.clear();
  markers_.clear();
}

void ChartData::addRun(const QString& name) {
  if (runCount() >= kMaxRuns) return;
  runs_.push_back({name, SampleHistory()});
}

void ChartData::removeRun(int runIndex) {
  if (runIndex < 0 || runIndex >= runCount() || runCount() == 1) return;
  runs_.erase(runs_.begin() + runIndex);
}

void ChartData::renameRun(int runIndex, const QString& name) {
  if (runIndex < 0 || runIndex >= runCount()) return;
  runs_[runIndex].name = name;
}

void ChartData::setBaselineShown(bool shown) {
  if (!shown) baseline_.history.clear();
  baselineShown_ = shown;
}

QStringList ChartData::runNames() const {
  QStringList names;
  for (const Run& run : runs_)
    names.append(run.name);
  return names;
}

void ChartData::addSample(int runIndex, const Metrics& metrics, const Divergence& fromRunZero) {
  const bool isRun = runIndex >= 0 && runIndex < runCount();
  if (!isRun && !(runIndex == kBaseline && baselineShown_)) return;
  run(runIndex).history.add(chartSampleFrom(metrics, fromRunZero));
}

void ChartData::addMarker(double time, const QString& label) {
  markers_.push_back({time, label});
  if (markers_.size() > kMaxMarkers) markers_.pop_front();
}

void ChartData::replaceNewestMarker(double time, const QString& label) {
  if (markers_.empty()) {
    addMarker(time, label);
  } else {
    markers_.back() = {time, label};
  }
}

template <class Action>
void ChartData::forEachHistory(Action&& action) const {
  for (const Run& run : runs_)
    action(run.history);
  if (baselineShown_) action(baseline_.history);
}

void ChartData::dropAfter(double time) {
  for (Run& run : runs_)
    run.history.dropAfter(time);
  baseline_.history.dropAfter(time);
  while (!markers_.empty() && markers_.back().time > time)
    markers_.pop_back();
}

bool ChartData::hasSamples() const {
  bool found = false;
  forEachHistory([&found](const SampleHistory& history) { found = found || !history.empty(); });
  return found;
}

double ChartData::startTime() const {
  bool found = false;
  double start = 0.0;
  forEachHistory([&](const SampleHistory& history) {
    if (history.empty()) return;
    start = found ? std::min(start, history.first().time) : history.first().time;
    found = true;
  });
  return start;
}

double ChartData::endTime() const {
  bool found = false;
  double end = 0.0;
  forEachHistory([&](const SampleHistory& history) {
    if (history.empty()) return;
    end = found ? std::max(end, history.latest().time) : history.latest().time;
    found = true;
  });
  return end;
}

}  // namespace fooball::gui
