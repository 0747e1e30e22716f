#pragma once

#include <QString>
#include <QStringList>
#include <deque>
#include <vector>

#include "fooball/divergence.h"
#include "fooball/metrics.h"
#include "fooball/run_group.h"
#include "sample_history.h"

namespace fooball::gui {

/// A vertical mark on the time axis: a mouse interaction or a setting change.
struct ChartMarker {
  double time = 0.0;  ///< s, simulated
  QString label;      ///< e.g. "gravity", "grab"
};

/// What the chart panel shows, kept apart from how it shows it: each run's name and sample
/// history, the chaos baseline's, and the markers on the time axis. Memory stays bounded
/// however long the run (about 1.5 MB per run's history).
///
/// Runs are numbered as in the RunGroup they mirror: run 0 is the reference. Adding, removing
/// and renaming runs keeps every other run's history, so entering, changing and leaving
/// compare mode loses nothing; only reset() starts over.
class ChartData {
 public:
  /// As many runs as a run group holds.
  static constexpr int kMaxRuns = static_cast<int>(RunGroup::kMaxRuns);
  /// The run index that stands for the chaos baseline in history() and addSample().
  static constexpr int kBaseline = -1;
  /// Beyond this many markers the oldest are dropped, so drawing them stays cheap.
  static constexpr std::size_t kMaxMarkers = 1000;

  ChartData();

  /// Starts over with the named runs (at most kMaxRuns are kept; none means one unnamed run):
  /// every history, the baseline's and the markers are cleared. Whether the baseline is shown
  /// stays as it was.
  void reset(const QStringList& runNames);
  /// Appends a run with an empty history; ignored when kMaxRuns are there.
  void addRun(const QString& name);
  /// Drops run `runIndex`'s history; the later runs move down one. Ignored for an index that is
  /// not a run, and for the last run left.
  void removeRun(int runIndex);
  void renameRun(int runIndex, const QString& name);
  /// Hiding the baseline drops its history: a run group drops the baseline then, and one
  /// turned on again starts afresh from run 0's state, so the old curve would not continue.
  void setBaselineShown(bool shown);
  bool baselineShown() const { return baselineShown_; }

  /// One state of run `runIndex`, or of the baseline (kBaseline) while it is shown, with its
  /// divergence from run 0 then. Ignored for any other index.
  void addSample(int runIndex, const Metrics& metrics, const Divergence& fromRunZero);
  void addMarker(double time, const QString& label);
  /// Moves the newest marker to `time` with `label` (one gesture going on); adds one if there is
  /// none.
  void replaceNewestMarker(double time, const QString& label);
  /// Forgets every sample and marker after `time` (s): the runs were rewound to it.
  void dropAfter(double time);

  int runCount() const { return static_cast<int>(runs_.size()); }
  QStringList runNames() const;
  const QString& runName(int runIndex) const { return runs_[runIndex].name; }
  /// `runIndex` is a run or kBaseline.
  const SampleHistory& history(int runIndex) const { return run(runIndex).history; }
  const std::deque<ChartMarker>& markers() const { return markers_; }

  /// Whether a run (or the shown baseline) holds a sample.
  bool hasSamples() const;
  /// s: the earliest first sample and the latest sample over all runs and the shown baseline
  /// (0 when there are none).
  double startTime() const;
  double endTime() const;

 private:
  struct Run {
    QString name;
    SampleHistory history;
  };

  Run& run(int runIndex) { return runIndex == kBaseline ? baseline_ : runs_[runIndex]; }
  const Run& run(int runIndex) const { return runIndex == kBaseline ? baseline_ : runs_[runIndex]; }
  /// Every run's history, and the baseline's while it is shown.
  template <class Action>
  void forEachHistory(Action&& action) const;

  std::vector<Run> runs_;  ///< reserved for kMaxRuns: adding one moves no history
  Run baseline_;
  bool baselineShown_ = false;
  std::deque<ChartMarker> markers_;
};

}  // namespace fooball::gui
