#pragma once

#include <QStringList>
#include <QWidget>
#include <optional>

#include "charts/axis_scale.h"
#include "fooball/gas_statistics.h"

class QScrollArea;

namespace fooball {
class RunGroup;
}

namespace fooball::gui {

class GasReadout;
class SpeedHistogramChart;

/// The Statistics dock's contents: the speed histograms with the Maxwell–Boltzmann curve beside
/// the table of temperature, pressure and collision rate against the hard-disk theory (issue
/// #16). The measuring is the engine's GasMonitor; this panel only asks it, while it is on
/// screen, and draws the answer. The speed axis (and with it the bins) keeps its range while the
/// speeds fit it and fill a third of it (followValues), so it does not jitter from refresh to
/// refresh.
class StatisticsPanel : public QWidget {
  Q_OBJECT

 public:
  explicit StatisticsPanel(QWidget* parent = nullptr);

  /// The runs' labels, run order; after runs were added, removed or replaced the windows start
  /// afresh.
  void showRuns(const QStringList& labels);
  /// Forgets the windows and the speed axis: a new scene, a restart.
  void restart();
  /// Measures `group` and draws it now, if the panel is on screen; does nothing otherwise (the
  /// dock closed, or behind the charts' tab).
  void refresh(const RunGroup& group);
  /// Shown in an open dock, and not behind the charts' tab.
  bool onScreen() const;
  /// Refreshes that measured something since the panel was made.
  int refreshCount() const { return refreshes_; }

  SpeedHistogramChart* histogram() const { return histogram_; }
  GasReadout* readout() const { return readout_; }
  /// What the last refresh measured.
  const GasMonitor::Snapshot& latest() const { return monitor_.latest(); }

 protected:
  void resizeEvent(QResizeEvent* event) override;
  void hideEvent(QHideEvent* event) override;

 private:
  /// The scroll area's least height: the table's, up to a share of the panel's.
  void fitTableHeight();

  SpeedHistogramChart* histogram_;
  GasReadout* readout_;
  QScrollArea* tableScroll_;
  GasMonitor monitor_;
  QStringList labels_;
  bool runsShown_ = false;
  std::optional<AxisScale> speedScale_;
  int refreshes_ = 0;
};

}  // namespace fooball::gui
