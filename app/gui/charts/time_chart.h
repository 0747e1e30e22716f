#pragma once

#include <QChartView>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <deque>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "axis_scale.h"
#include "chart_data.h"
#include "chart_sample.h"
#include "sample_history.h"

class QAbstractAxis;
class QLineSeries;
class QLogValueAxis;
class QValueAxis;

namespace fooball::gui {

class MarkerOverlay;

/// px on the left and right of a chart's plot area.
struct PlotInsets {
  double left = 0.0;
  double right = 0.0;
};

/// One chart of the panel: a few quantities of some runs against simulated time, on a dark
/// plot, with the markers over it. It draws what it is given and keeps no samples itself.
class TimeChart : public QChartView {
 public:
  /// Points per curve, however many samples: a lowest and a highest value per pixel column of
  /// the plot, within these bounds.
  static constexpr int kMaxPointsPerCurve = 2000;
  static constexpr int kMinPointsPerCurve = 200;

  /// A log value axis draws only positive values.
  enum class ValueAxisKind { Linear, Logarithmic };

  /// A run whose quantities the chart draws.
  struct CurveOwner {
    int run = 0;    ///< index into redraw()'s histories, or ChartData::kBaseline
    QString label;  ///< the curves' name (legend entries, in single-run colours)
  };

  TimeChart(const QString& title, std::vector<Quantity> quantities,
            const std::deque<ChartMarker>* markers,
            ValueAxisKind valueAxisKind = ValueAxisKind::Linear, QWidget* parent = nullptr);

  /// One curve per quantity and owner. `colourByRun` is compare mode: each run's curves in its
  /// colour, a line style per quantity, and a legend that names the styles (the panel's run
  /// legend names the colours); otherwise each quantity has its own colour and legend entry.
  /// The baseline's curves are grey and dashed whatever the mode, with a legend entry of their
  /// own.
  void setOwners(const std::vector<CurveOwner>& owners, bool colourByRun);
  bool hasCurves() const { return !curves_.empty(); }
  void setQuantityShown(Quantity quantity, bool shown);
  bool showsAnyQuantity() const;

  /// The value axis' title: `name` and, in brackets, `unit` ("J"; "" for a ratio) with the power
  /// of ten the values are drawn in when they are tiny or huge (displayExponent).
  void setValueAxisTitle(const QString& name, const QString& unit);
  void setMarkerLabelsShown(bool shown);
  /// The next redraw fits the value axis to the data afresh instead of keeping its range.
  void forgetValueScale();

  /// Redraws every shown curve from its owner's history (`histories[run]`, or `baseline`) on the
  /// time axis `timeScale`: one replace() per curve from a buffer that keeps its capacity.
  void redraw(std::span<const SampleHistory* const> histories, const SampleHistory* baseline,
              const AxisScale& timeScale);

  /// Points in the curves of `run` (the largest count over its shown quantities).
  int pointCount(int run) const;
  /// The points `run`'s curve of the chart's `quantityIndex`-th quantity holds (none when it
  /// has no such curve or it is hidden), in the value axis' units (see the axis title), and its
  /// pen (Qt::NoPen then).
  QList<QPointF> points(int run, int quantityIndex) const;
  QPen pen(int run, int quantityIndex) const;
  /// The value axis as a user reads it: its title, and the tick labels drawn in the chart's
  /// scene, top to bottom.
  QString valueAxisTitle() const;
  QStringList valueTickLabels() const;
  /// The value axis' range, as last drawn, in its units (see the axis title).
  std::pair<double, double> valueRange() const;
  int visibleMarkerCount() const;

  /// px from the chart's edges to its plot area's without the extra margins below: on the left
  /// the room the value axis takes, on the right what the last time label overhangs; as of the
  /// last layout, none before the first.
  std::optional<PlotInsets> naturalPlotInsets() const { return naturalPlotInsets_; }
  /// Extra margins (px) that line this chart's plot area up with its neighbours'.
  void setExtraMargins(PlotInsets pixels);
  PlotInsets extraMargins() const { return extraMargins_; }

 protected:
  /// QChartView keeps the largest least width its chart ever had (it widens its minimum to the
  /// chart's on every resize, never narrows it): a chart once laid out wide, or with wide margins
  /// for a moment, would hold its dock and the window at that width. The chart's own least
  /// width, now, is the view's.
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Curve {
    Quantity quantity;
    int run;
    QLineSeries* series;
    QList<QPointF> points;  ///< in the quantity's own units; reused on every redraw
  };

  /// An empty series that only puts an entry in the legend: in compare mode a quantity's line
  /// style, once for all runs, and the baseline's look.
  struct LegendKey {
    QLineSeries* series;
    std::optional<Quantity> quantity;  ///< none for the baseline's key
  };

  const Curve* findCurve(int run, int quantityIndex) const;
  bool isShown(Quantity quantity) const;
  bool logarithmic() const { return logAxis_ != nullptr; }
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
  /// Fits the value axis to shownValues_ for the plot's current height. Returns whether the
  /// curves' power of ten changed (their series then need showCurves()).
  bool fitValueAxis();
  /// Hands every shown curve's points to its series, divided by 10^displayExponent_.
  void showCurves();
  void updateValueAxisTitle();

  QChart* chart_;
  QValueAxis* timeAxis_;
  /// The value axis: one of these two, the other null.
  QValueAxis* linearAxis_ = nullptr;
  QLogValueAxis* logAxis_ = nullptr;
  QAbstractAxis* valueAxis_ = nullptr;
  MarkerOverlay* markerOverlay_;
  std::vector<Quantity> quantities_;
  std::vector<Quantity> hiddenQuantities_;
  std::vector<Curve> curves_;
  std::vector<LegendKey> legendKeys_;
  bool colourByRun_ = false;
  ValueRange shownValues_;  ///< of the shown curves, as last drawn
  std::optional<AxisScale> valueScale_;
  std::optional<LogAxisScale> logValueScale_;
  int valueTicks_ = 0;           ///< tick intervals the value scale was chosen for
  int displayExponent_ = 0;      ///< the linear value axis shows values in units of 10^this
  QList<QPointF> scaledPoints_;  ///< one curve's points in those units; reused
  QString valueName_;
  QString valueUnit_;
  std::optional<PlotInsets> naturalPlotInsets_;
  PlotInsets extraMargins_;
};

}  // namespace fooball::gui
