#pragma once

#include <QString>
#include <QStringList>
#include <array>
#include <deque>

#include "fooball/metrics.h"
#include "sample_history.h"

namespace fooball::gui {

/// A vertical mark on the time axis: a mouse interaction or a setting change.
struct ChartMarker {
  double time = 0.0;  ///< s, simulated
  QString label;      ///< e.g. "gravity", "grab"
};

/// What the chart panel shows, kept apart from how it shows it: each run's name and sample
/// history, and the markers on the time axis. Memory stays bounded however long the run.
class ChartData {
 public:
  /// One run, or two in compare mode.
  static constexpr int kMaxRuns = 2;
  /// Beyond this many markers the oldest are dropped, so drawing them stays cheap.
  static constexpr std::size_t kMaxMarkers = 1000;

  /// Starts over with the named runs (at most kMaxRuns are kept; none means one unnamed run).
  void reset(const QStringList& runNames);
  /// Ignored for a run index that reset() did not name.
  void addSample(int runIndex, const Metrics& metrics);
  void addMarker(double time, const QString& label);

  int runCount() const { return static_cast<int>(runNames_.size()); }
  const QStringList& runNames() const { return runNames_; }
  const SampleHistory& history(int runIndex) const { return runs_[runIndex].history; }
  const std::deque<ChartMarker>& markers() const { return markers_; }

  bool hasSamples() const;
  /// s: the earliest first sample and the latest sample over all runs (0 when there are none).
  double startTime() const;
  double endTime() const;

 private:
  struct Run {
    SampleHistory history;
    double initialTotalEnergy = 0.0;  ///< J, E₀ for the relative residual
  };

  QStringList runNames_{QString()};
  std::array<Run, kMaxRuns> runs_;
  std::deque<ChartMarker> markers_;
};

}  // namespace fooball::gui
