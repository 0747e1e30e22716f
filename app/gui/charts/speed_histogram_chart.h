#pragma once

#include <QChartView>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QStringList>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "axis_scale.h"
#include "fooball/speed_distribution.h"

class QAreaSeries;
class QLineSeries;
class QValueAxis;

namespace fooball::gui {

/// The statistics dock's chart: every run's speed histogram as an outline over a translucent
/// fill in its run colour (overlaid in compare mode), and the balls per bin that 2D
/// Maxwell–Boltzmann expects as a dashed light curve through the bins' centres. It draws what it
/// is given and measures nothing.
class SpeedHistogramChart : public QChartView {
 public:
  explicit SpeedHistogramChart(QWidget* parent = nullptr);

  /// One histogram per run, named in the legend by `labels` (run order). `curveName` names the
  /// Maxwell–Boltzmann curve: at whose temperature it is drawn.
  void setRuns(const QStringList& labels, const QString& curveName);

  /// Redraws: `histograms[k]` is run k's (all over the same bins, at most setRuns' count),
  /// `expected` the curve's balls per bin (none: no curve), on the speed axis `speedScale`
  /// (m/s, from 0 to the histograms' range).
  void draw(std::span<const SpeedHistogram* const> histograms, std::span<const double> expected,
            const AxisScale& speedScale);

  int histogramCount() const { return static_cast<int>(histograms_.size()); }
  /// Run `run`'s outline as drawn: for bin k the points (k·w, count) and ((k+1)·w, count), so
  /// the even-numbered points' y are the counts, bin by bin.
  QList<QPointF> histogramPoints(int run) const;
  QPen histogramPen(int run) const;
  QBrush histogramBrush(int run) const;
  QString histogramName(int run) const;
  /// The curve's points (bin centre in m/s, balls) as drawn.
  QList<QPointF> curvePoints() const;
  std::pair<double, double> speedRange() const;
  std::pair<double, double> countRange() const;
  QString speedAxisTitle() const;

 private:
  QChart* chart_;
  QValueAxis* speedAxis_;
  QValueAxis* countAxis_;
  std::vector<QAreaSeries*> histograms_;
  QLineSeries* curve_;
  std::optional<AxisScale> countScale_;
  QList<QPointF> points_;  ///< one outline's points; reused on every redraw
};

}  // namespace fooball::gui
