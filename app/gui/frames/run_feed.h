#pragma once

#include <QElapsedTimer>
#include <QString>

class QWidget;

namespace fooball::gui {

class ChartPanel;
class CompareReadout;
class RunController;
class SettingsSidebar;
class StatisticsPanel;

/// The one way from the run group's state to what shows it: the charts' samples and change
/// markers, the compare readout, the sidebar's counters and inspector, and the gas statistics.
/// The frame loop calls it every few frames; the window after loads, restarts and rewinds. Each
/// readout is measured only while it is on screen.
class RunFeed {
 public:
  /// Where the state goes. `sidebarDock` holds the sidebar: its counters are measured only while
  /// both are shown.
  struct Targets {
    ChartPanel& charts;
    CompareReadout& compareReadout;
    SettingsSidebar& sidebar;
    QWidget& sidebarDock;
    StatisticsPanel& statistics;
  };

  RunFeed(const RunController& runs, Targets targets);

  /// Every run's metrics and divergence (and the chaos baseline's) as the charts' next sample.
  void sampleCharts();
  /// Every run's divergence in the compare readout and its counters in the sidebar, each only
  /// while on screen (also while paused).
  void showReadouts();
  /// The selected ball (or none) in the sidebar's inspector.
  void showSelectedBall();
  /// Measures and draws the gas statistics, if their dock is on screen (nothing otherwise).
  void showStatistics();
  /// The runs' labels in the compare readout, the counters and the statistics, then their
  /// figures (showReadouts).
  void showRuns();
  /// The newest run joins the charts (and the chaos baseline, if on), sampled now.
  void addRun();
  /// Run `index` leaves the charts.
  void removeRun(int index);
  /// Run `index` has a new label (another backend or options) in the charts.
  void renameRun(int index);
  /// The runs' labels in the compare readout (after a run's options changed).
  void showLabels();
  /// The chaos baseline's curves on or off, sampled now.
  void showBaseline(bool on);
  /// The charts and statistics start over on the runs' state now (a load, restart or reset).
  void restart();
  /// The charts end at `time` (s), where a rewind left the runs, with a sample of now.
  void dropAfter(double time);

  /// A vertical mark on the charts' time axis at the time of now. Changes of one `gesture`
  /// ("gravity": a slider dragged through many values) in quick succession are one marker, which
  /// moves along and shows the latest value.
  void markChange(const QString& label, const QString& gesture = {});
  /// A mark at `time` (s), e.g. where the runs restarted identical.
  void markAt(double time, const QString& label);

 private:
  const RunController& runs_;
  Targets to_;
  QString lastGesture_;         ///< markChange's, while it may go on
  QElapsedTimer gestureClock_;  ///< since its last change
};

}  // namespace fooball::gui
