#pragma once

#include <QChartView>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QStringList>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "axis_scale.h"
#include "chart_data.h"
#include "chart_sample.h"
#include "sample_history.h"

class QLineSeries;
class QValueAxis;

namespace fooball::gui {

class MarkerOverlay;

/// px on the left and right of a chart's plot area.
struct PlotInsets {
  double left = 0.0;
  double right = 0.0;
};

/// One chart of the panel: a few quantities of every run against simulated time, on a dark
/// plot, with the markers over it. It draws what it is given and keeps no samples itself.
class TimeChart : public QChartView {
 public:
  /// Points per curve, however many samples: a lowest and a highest value per pixel column of
  /// the plot, within these bounds.
  static constexpr int kMaxPointsPerCurve = 2000;
  static constexpr int kMinPointsPerCurve = 200;

  TimeChart(const QString& title, std::vector<Quantity> quantities,
            const std::deque<ChartMarker>* markers, QWidget* parent = nullptr);

  /// One curve per quantity and run; compare mode when there are two runs.
  void setRuns(const QStringList& runNames);
  void setQuantityShown(Quantity quantity, bool shown);
  bool showsAnyQuantity() const;

  void setValueAxisTitle(const QString& title);
  /// The time axis' tick labels and title. The panel's charts share one time axis, so only the
  /// bottom one labels it (the others keep its grid lines): room for taller plots.
  void setTimeAxisLabelsShown(bool shown);
  void setMarkerLabelsShown(bool shown);
  /// The next redraw fits the value axis to the data afresh instead of keeping its range.
  void forgetValueScale();

  /// Redraws every shown curve from its run's history (`histories[runIndex]`) on the time axis
  /// `timeScale`: one replace() per curve from a buffer that keeps its capacity.
  void redraw(std::span<const SampleHistory* const> histories, const AxisScale& timeScale);

  /// Points in the curves of run `runIndex` (the largest count over its shown quantities).
  int pointCount(int runIndex) const;
  int visibleMarkerCount() const;

  /// px from the chart's edges to its plot area's without the extra margins below: on the left
  /// the room the value axis takes, on the right what the last time label overhangs; as of the
  /// last layout, none before the first.
  std::optional<PlotInsets> naturalPlotInsets() const { return naturalPlotInsets_; }
  /// Extra margins (px) that line this chart's plot area up with its neighbours'.
  void setExtraMargins(PlotInsets pixels);
  PlotInsets extraMargins() const { return extraMargins_; }

 private:
  struct Curve {
    Quantity quantity;
    int runIndex;
    QLineSeries* series;
    QList<QPointF> points;  ///< reused on every redraw
  };

  /// An empty series that only puts an entry in the legend. In compare mode the legend names
  /// the runs (their colours) and the quantities (their line styles) once each, rather than
  /// every run × quantity pair.
  struct LegendKey {
    QLineSeries* series;
    std::optional<Quantity> quantity;  ///< none for a run's key
  };

  bool isShown(Quantity quantity) const;
  int maxPointsPerCurve() const;
  QLineSeries* addSeries(const QString& name, const QPen& pen);
  void removeAllSeries();
  /// Series and legend entries follow the shown quantities.
  void applyShownQuantities();
  /// As many value tick intervals as `plotArea` has room for.
  static int valueTicksFor(const QRectF& plotArea);
  /// Tall enough for the title, legend, tick labels and axis titles shown, and a plot as tall
  /// as the value axis' title: a shorter chart elides its labels to "…".
  void updateMinimumHeight();
  /// Fits the value axis to shownValues_ for the plot's current height.
  void fitValueAxis();

  QChart* chart_;
  QValueAxis* timeAxis_;
  QValueAxis* valueAxis_;
  MarkerOverlay* markerOverlay_;
  std::vector<Quantity> quantities_;
  std::vector<Quantity> hiddenQuantities_;
  std::vector<Curve> curves_;
  std::vector<LegendKey> legendKeys_;
  ValueRange shownValues_;  ///< of the shown curves, as last drawn
  std::optional<AxisScale> valueScale_;
  int valueTicks_ = 0;  ///< tick intervals valueScale_ was chosen for
  std::optional<PlotInsets> naturalPlotInsets_;
  PlotInsets extraMargins_;
};

}  // namespace fooball::gui
