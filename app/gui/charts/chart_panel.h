#pragma once

#include <QColor>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <array>
#include <cstddef>

#include "chart_data.h"
#include "fooball/metrics.h"

class QAction;
class QDoubleSpinBox;
class QTimer;
class QToolBar;

namespace fooball::gui {

class TimeChart;

/// The live charts against simulated time: momentum, energy and the energy budget's residual,
/// for one run or two overlaid (compare mode), with markers for interactions and setting
/// changes. Samples go into bounded histories; a timer redraws at most 10 times a second, and
/// each curve holds at most two points per pixel column, so the charts cost the same however
/// long the run and never hold the simulation back.
class ChartPanel : public QWidget {
  Q_OBJECT

 public:
  /// The charts, top to bottom, for displayedPointCount().
  enum Chart : int { kMomentumChart = 0, kEnergyChart = 1, kResidualChart = 2 };
  static constexpr int kChartCount = 3;

  explicit ChartPanel(QWidget* parent = nullptr);
  ~ChartPanel() override;

  /// Starts over (new scene, restart): clears every series and marker. `runs` names the curves'
  /// owners: one backend name, or two in compare mode (e.g. {"elastic", "exact"}).
  void reset(const QStringList& runs);
  /// One state of run `runIndex` (0 or 1; others are ignored). Cheap: stores into a history;
  /// the view is redrawn by a timer, not per sample.
  void addSample(int runIndex, const fooball::Metrics& metrics);
  /// A vertical mark on the time axis (s): a mouse interaction or a setting change ("gravity",
  /// "grab").
  void addMarker(double time, const QString& label);
  /// Scrolling window (seconds of simulated time, whole seconds from 1 s to 1 h) vs the whole
  /// run.
  void setWindowSeconds(double seconds);  // default 20 s
  void setShowWholeRun(bool whole);
  /// File → Export: PNG of the charts as laid out at the panel's size (also while hidden), at
  /// twice the screen's pixels; CSV of every stored sample (header + one row per sample per
  /// run, with a `run` column holding the run's name). False when the file was not written.
  bool exportPng(const QString& path) const;
  bool exportCsv(const QString& path) const;
  /// For tests: points the view currently holds for `runIndex` in chart `chart` (after a
  /// refresh; the largest count over that run's shown curves), and samples stored.
  int displayedPointCount(int chart, int runIndex) const;
  std::size_t storedSampleCount(int runIndex) const;
  /// Markers held, and those inside the time axis's current range (drawn, after a refresh).
  int markerCount() const;
  int displayedMarkerCount() const;
  /// Redraws now (the timer calls it; tests call it directly).
  void refresh();

  /// The colour of run `runIndex`'s curves in compare mode, for anything that should match.
  static QColor runColour(int runIndex);

 private:
  QToolBar* createToolBar();
  QAction* addQuantityToggle(QToolBar* toolBar, const QString& text, const QString& toolTip,
                             const QString& objectName);
  /// Shows and hides curves and charts as the toggles say.
  void applyToggles();
  /// Lines up the charts' plot areas, so one time is at one x in every chart.
  void alignPlotAreas();
  void redraw() const;

  ChartData data_;
  std::array<TimeChart*, kChartCount> charts_{};
  QWidget* chartArea_ = nullptr;

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

  QTimer* refreshTimer_ = nullptr;
  /// The view is a cache of data_: redrawing it changes nothing the panel holds, so a const
  /// export may bring it up to date.
  mutable bool viewOutOfDate_ = true;
};

}  // namespace fooball::gui
