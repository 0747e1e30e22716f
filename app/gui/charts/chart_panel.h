#pragma once

#include <QColor>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "chart_data.h"
#include "fooball/divergence.h"
#include "fooball/metrics.h"

class QAction;
class QDoubleSpinBox;
class QLabel;
class QGridLayout;
class QScrollArea;
class QTimer;
class QToolBar;

namespace fooball::gui {

class TimeChart;

/// How many columns `charts` charts get in `area` (px): each as large as it can be at about
/// 2.4 : 1, none narrower than 240 px beside another.
int chartColumns(int charts, QSize area);

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
  /// For tests: points the view currently holds for `runIndex` (or kBaselineRun) in chart
  /// `chart` (after a refresh; the largest count over that run's shown curves), and samples
  /// stored.
  int displayedPointCount(int chart, int runIndex) const;
  std::size_t storedSampleCount(int runIndex) const;
  /// For tests: the points a chart plots for a run (after a refresh), `curve` numbering the
  /// chart's quantities as in Chart; empty for a hidden chart or curve. Their pen, and the
  /// value axis' range.
  QList<QPointF> displayedPoints(int chart, int runIndex, int curve = 0) const;
  QPen displayedPen(int chart, int runIndex, int curve = 0) const;
  std::pair<double, double> displayedYRange(int chart) const;
  /// `chart`'s value axis title and tick labels as drawn (TimeChart::valueTickLabels).
  QString displayedValueAxisTitle(int chart) const;
  QStringList displayedValueTickLabels(int chart) const;
  /// Whether `chart` is on screen: it has something to show and its toggles are on.
  bool chartShown(int chart) const;
  /// The run legend above the charts, as plain text (empty when it is hidden: one run).
  QString runLegendText() const;
  /// Markers held, and those inside the time axis's current range (drawn, after a refresh).
  int markerCount() const;
  /// The markers' labels, oldest first.
  QStringList markerLabels() const;
  int displayedMarkerCount() const;
  /// Redraws now (the timer calls it; tests call it directly).
  void refresh();

 private:
  QToolBar* createToolBar();
  /// Every chart's curves and the run legend follow the runs and the baseline.
  void rebuildCurves();
  bool isChartShown(const TimeChart* chart) const;
  QAction* addQuantityToggle(QToolBar* toolBar, const QString& text, const QString& toolTip,
                             const QString& objectName);
  /// Shows and hides curves and charts as the toggles say.
  void applyToggles();
  /// Puts the charts shown into the grid, in as many columns as suit the panel's shape.
  void arrangeCharts();
  bool eventFilter(QObject* watched, QEvent* event) override;
  /// Lines up the charts' plot areas, so one time is at one x in every chart.
  void alignPlotAreas();
  void redraw() const;

  ChartData data_;
  std::array<TimeChart*, kChartCount> charts_{};
  QWidget* chartArea_ = nullptr;  ///< the run legend and the charts: what exportPng draws
  QLabel* runLegend_ = nullptr;
  QWidget* chartGrid_ = nullptr;
  QGridLayout* gridLayout_ = nullptr;
  QScrollArea* scroll_ = nullptr;
  std::array<bool, kChartCount> chartsShown_{};
  int gridColumns_ = 0;                 ///< as last arranged, to see when that changes
  std::vector<TimeChart*> gridCharts_;  ///< the charts in the grid, in order

  QAction* wholeRunToggle_ = nullptr;
  QDoubleSpinBox* windowSpin_ = nullptr;  ///< s, the scrolling window's length
  QAction* momentumXToggle_ = nullptr;
  QAction* momentumYToggle_ = nullptr;
  QAction* momentumMagnitudeToggle_ = nullptr;
  QAction* kineticToggle_ = nullptr;
  QAction* potentialToggle_ = nullptr;
  QAction* totalToggle_ = nullptr;
  QAction* residualToggle_ = nullptr;
  QAction* relativeResidualToggle_ = nullptr;
  QAction* divergenceToggle_ = nullptr;

  QTimer* refreshTimer_ = nullptr;
  /// The view is a cache of data_: redrawing it changes nothing the panel holds, so a const
  /// export may bring it up to date.
  mutable bool viewOutOfDate_ = true;
};

}  // namespace fooball::gui
