#pragma once

#include <QColor>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <array>
#include <cstddef>
#include <vector>

#include "chart_data.h"
#include "fooball/divergence.h"
#include "fooball/metrics.h"

class QLabel;
class QComboBox;
class QTimer;

namespace fooball::gui {

class ChartGrid;
class ChartToolBar;
class TimeChart;

/// The live charts against simulated time: momentum, energy and the energy budget's residual
/// of every run overlaid (1 to 8, as in the run group), each run in its colour in compare mode,
/// and the divergence from run 0 of every other run and of the chaos baseline; with markers for
/// interactions and setting changes. Samples go into bounded histories; a timer redraws at most
/// 10 times a second, and each curve holds at most two points per pixel column, so the charts
/// cost the same however long the run and never hold the simulation back.
///
/// Runs are numbered as in the fooball::RunGroup: run 0 is the reference. Adding, removing and
/// renaming a run keeps every other run's history; only reset() starts over.
class ChartPanel : public QWidget {
  Q_OBJECT

 public:
  /// The charts, top to bottom, for displayedPointCount() and displayedPoints().
  enum Chart : int {
    kMomentumChart = 0,   ///< curves: px, py, |p|
    kEnergyChart = 1,     ///< curves: kinetic, potential, total
    kResidualChart = 2,   ///< curves: residual (J), residual / |E₀|
    kDivergenceChart = 3  ///< curves: RMS position difference from run 0 (log axis)
  };
  static constexpr int kChartCount = 4;
  /// The run index that stands for the chaos baseline in the queries below.
  static constexpr int kBaselineRun = ChartData::kBaseline;
  static constexpr int kMaxRuns = ChartData::kMaxRuns;

  explicit ChartPanel(QWidget* parent = nullptr);
  ~ChartPanel() override;

  /// Starts over (new scene, restart): clears every run's samples, the baseline's and the
  /// markers, with one curve set per label (1 to kMaxRuns; none means one unnamed run). A run's
  /// label is its run spec, e.g. {"elastic", "elastic:substeps=16", "exact"}. Whether the
  /// baseline is shown stays as it was.
  void reset(const QStringList& runLabels);
  /// Appends a run (compare mode begins, or grows); the others' history stays. Ignored when
  /// kMaxRuns are there.
  void addRun(const QString& label);
  /// Drops run `runIndex`'s history; later runs shift down one (their colours with them, as a
  /// colour belongs to a run index). Ignored for the last run left.
  void removeRun(int runIndex);
  /// A run's spec changed: the legend and the CSV's run column follow; its history stays.
  void renameRun(int runIndex, const QString& label);
  /// Whether the chaos baseline's curves exist. Hiding them drops the baseline's history (the
  /// run group drops the baseline, and one turned on again starts afresh from run 0's state).
  void setBaselineShown(bool shown);
  bool baselineShown() const { return data_.baselineShown(); }
  int runCount() const { return data_.runCount(); }

  /// One state of run `runIndex` and its divergence from run 0 then (zero for run 0). Cheap:
  /// stores into a history; the view is redrawn by a timer, not per sample. Ignored for an
  /// index that is not a run.
  void addSample(int runIndex, const fooball::Metrics& metrics,
                 const fooball::Divergence& fromRunZero);
  /// One state of the chaos baseline; ignored while it is not shown.
  void addBaselineSample(const fooball::Metrics& metrics, const fooball::Divergence& fromRunZero);
  /// A vertical mark on the time axis (s): a mouse interaction or a setting change ("gravity",
  /// "grab").
  void addMarker(double time, const QString& label);
  void replaceNewestMarker(double time, const QString& label);
  /// The runs were rewound to `time` (s): every sample and marker after it goes, so the charts
  /// end where the runs are and never show a future that no longer exists.
  void dropAfter(double time);
  /// Scrolling window (seconds of simulated time, whole seconds from 1 s to 1 h) vs the whole
  /// run.
  void setWindowSeconds(double seconds);  // default 20 s
  void setShowWholeRun(bool whole);
  /// File → Export: PNG of the charts (and the run legend) as laid out at the panel's size
  /// (also while hidden), at twice the screen's pixels, under `caption` (the scene and the runs;
  /// also stored as the PNG's "Description" text); CSV of every stored sample (header + one
  /// row per sample per run, with a `run` column holding the run's label, `baseline` for the
  /// chaos baseline). False when the file was not written.
  bool exportPng(const QString& path, const QString& caption = {}) const;
  bool exportCsv(const QString& path) const;
  /// For tests (tests/gui/chart_reading.h): the samples and markers held, chart `chart` (one of
  /// Chart) as drawn, whether it is on screen (it has something to show and its toggles are
  /// on), and the run legend above the charts (hidden for one run).
  const ChartData& data() const { return data_; }
  const TimeChart& chart(int chart) const { return *charts_.at(std::size_t(chart)); }
  bool chartShown(int chart) const;
  const QLabel& runLegend() const { return *runLegend_; }
  /// Redraws now (the timer calls it; tests call it directly).
  void refresh();

 private:
  /// Every chart's curves and the run legend follow the runs and the baseline.
  void rebuildCurves();
  bool isChartShown(const TimeChart* chart) const;
  std::vector<TimeChart*> shownCharts() const;
  /// Shows and hides curves and charts as the toggles say.
  void applyToggles();
  /// Puts as many of the charts shown as fit whole into the grid, in as many columns as suit
  /// the panel's shape, from the one the selector names; the selector shows when some do not.
  void arrangeCharts();
  bool eventFilter(QObject* watched, QEvent* event) override;
  /// Lines up the charts' plot areas, so one time is at one x in every chart.
  void alignPlotAreas();
  void redraw() const;

  ChartData data_;
  std::array<TimeChart*, kChartCount> charts_{};
  QWidget* chartArea_ = nullptr;  ///< the run legend and the charts: what exportPng draws
  QLabel* runLegend_ = nullptr;
  QComboBox* selector_ = nullptr;  ///< the chart shown first, when not all fit
  ChartGrid* chartGrid_ = nullptr;

  ChartToolBar* toolBar_ = nullptr;

  QTimer* refreshTimer_ = nullptr;
  /// The view is a cache of data_: redrawing it changes nothing the panel holds, so a const
  /// export may bring it up to date.
  mutable bool viewOutOfDate_ = true;
};

}  // namespace fooball::gui
