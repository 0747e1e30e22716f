#include "compare_chart.h"

#include <QCategoryAxis>
#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "chart_image.h"
#include "fooball/metrics.h"
#include "offscreen_qt.h"
#include "run_palette.h"

namespace fooball::plots {

namespace {

/// The run's colour in the app (by run order, not backend: one backend may appear in several
/// runs); the chaos baseline dashed in its grey.
QPen curvePen(const CompareCurve& curve, std::size_t run) {
  if (curve.baseline) return QPen(colours::neutralColour(), 2.0, Qt::DashLine);
  return QPen(colours::runColour(static_cast<int>(run)), 2.0);
}

QLineSeries* curveSeries(const CompareCurve& curve, std::size_t run) {
  auto* series = new QLineSeries;
  series->setName(QString::fromStdString(curve.label));
  series->setPen(curvePen(curve, run));
  return series;
}

QValueAxis* timeAxis(double duration) {
  auto* axis = new QValueAxis;
  axis->setTitleText("time (s)");
  axis->setRange(0.0, duration > 0.0 ? duration : 1.0);
  axis->setLabelFormat("%g");
  axis->setTickCount(6);
  return axis;
}

QChart* divergencePanel(const CompareChart& data) {
  auto* chart = new QChart;
  chart->setTitle(QString("RMS distance from run 0 (%1)")
                      .arg(QString::fromStdString(data.curves.front().label)));
  chart->legend()->setAlignment(Qt::AlignBottom);
  double least = std::numeric_limits<double>::infinity();
  double most = 0.0;
  std::vector<QLineSeries*> series;
  // Run 0's own divergence is 0 throughout: a log axis has nowhere to draw it.
  for (std::size_t run = 1; run < data.curves.size(); ++run) {
    const CompareCurve& curve = data.curves[run];
    QLineSeries* line = curveSeries(curve, run);
    for (std::size_t i = 0; i < curve.times.size(); ++i) {
      const double value = curve.rmsDivergence[i];
      if (!(value > 0.0) || !std::isfinite(value)) continue;  // zeros: not on a log axis
      line->append(curve.times[i], value);
      least = std::min(least, value);
      most = std::max(most, value);
    }
    series.push_back(line);
  }
  if (data.departThreshold > 0.0) {
    auto* threshold = new QLineSeries;
    threshold->setName(
        QString("10% of the mean radius (%1 m)").arg(data.departThreshold, 0, 'g', 3));
    threshold->setPen(QPen(Qt::black, 1.0, Qt::DotLine));
    threshold->append(0.0, data.departThreshold);
    threshold->append(data.duration, data.departThreshold);
    least = std::min(least, data.departThreshold);
    most = std::max(most, data.departThreshold);
    series.push_back(threshold);
  }
  if (!std::isfinite(least)) least = most = 1.0;  // nothing to draw: any decade will do

  QValueAxis* xAxis = timeAxis(data.duration);
  QLogValueAxis* yAxis = decadeAxis("RMS position difference (m)", least, most, "%.0e");
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  for (QLineSeries* line : series)
    addSeries(chart, line, xAxis, yAxis, true);
  return chart;
}

/// y = sign(r)·log10(1 + |r|/c): linear within about ±c, one unit per decade beyond it.
///
/// Why a symmetric log: the residuals of the methods span many decades (exact impulses stay at
/// rounding, ~1e-15 of E, while a solver with float state reaches 1e-4 in a gas), so a linear
/// axis shows only the worst run and flattens the others onto 0; a log axis of
/// |residual| would hide whether a method gains or loses energy, which is half the story. The
/// symmetric log keeps the sign and gives every run its decade.
struct SymmetricLog {
  double linearWithin;  ///< c, in the plotted unit

  double operator()(double r) const {
    return std::copysign(std::log10(1.0 + std::abs(r) / linearWithin), r);
  }
};

QString decadeLabel(int exponent, bool negative) {
  const QString magnitude = exponent == 0 ? QString("1") : QString("1e%1").arg(exponent);
  return negative ? "-" + magnitude : magnitude;
}

QChart* residualPanel(const CompareChart& data) {
  // Relative where every run has an E(0) to be relative to (the runs start from one state).
  const bool relative =
      std::all_of(data.curves.begin(), data.curves.end(),
                  [](const CompareCurve& curve) { return curve.initialEnergy != 0.0; });
  const auto plotted = [relative](const CompareCurve& curve, std::size_t i) {
    return relative ? relativeEnergyError(curve.energyResidual[i], curve.initialEnergy)
                    : curve.energyResidual[i];
  };
  double leastMagnitude = std::numeric_limits<double>::infinity();
  double mostPositive = 0.0;
  double mostNegative = 0.0;  // as a magnitude
  for (const CompareCurve& curve : data.curves) {
    for (std::size_t i = 0; i < curve.energyResidual.size(); ++i) {
      const double r = plotted(curve, i);
      if (!std::isfinite(r) || r == 0.0) continue;
      leastMagnitude = std::min(leastMagnitude, std::abs(r));
      (r > 0.0 ? mostPositive : mostNegative) =
          std::max(r > 0.0 ? mostPositive : mostNegative, std::abs(r));
    }
  }
  // The linear part: the smallest residual's decade, but no more than 12 decades under the
  // largest (lower ones are rounding and would only crowd the axis), and for a relative residual
  // not under 1e-16, the rounding of a double.
  const double most = std::max(mostPositive, mostNegative);
  double linearWithin = relative ? 1e-16 : 1e-12;
  if (most > 0.0) {
    linearWithin =
        std::max({decadeBelow(leastMagnitude), decadeAbove(most) * 1e-12, relative ? 1e-16 : 0.0});
  }
  const SymmetricLog transform{linearWithin};
  const auto decadesFor = [&](double magnitude) {
    return magnitude > linearWithin
               ? static_cast<int>(std::ceil(std::log10(magnitude / linearWithin) - 1e-9))
               : 1;
  };
  // A label every decade up to six of them on a side, every second or third beyond; each side
  // ends on a labelled decade.
  const int labelEvery =
      1 +
      (std::max(decadesFor(mostPositive), mostNegative > 0.0 ? decadesFor(mostNegative) : 0) - 1) /
          6;
  const auto roundedUp = [&](int decades) {
    return (decades + labelEvery - 1) / labelEvery * labelEvery;
  };
  const int positiveDecades = roundedUp(decadesFor(mostPositive));
  const int negativeDecades = mostNegative > 0.0 ? roundedUp(decadesFor(mostNegative)) : 0;
  const int firstExponent = static_cast<int>(std::lround(std::log10(linearWithin)));

  auto* yAxis = new QCategoryAxis;
  yAxis->setTitleText(relative ? "energy residual / |E(0)| (symmetric log)"
                               : "energy residual, J (symmetric log)");
  yAxis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
  // No label at ±c itself: it sits a third of a decade from 0 and the labels would overlap.
  std::vector<std::pair<QString, double>> ticks;
  for (int k = negativeDecades; k >= labelEvery; k -= labelEvery) {
    ticks.emplace_back(decadeLabel(firstExponent + k, true),
                       transform(-linearWithin * std::pow(10.0, k)));
  }
  ticks.emplace_back("0", 0.0);
  for (int k = labelEvery; k <= positiveDecades; k += labelEvery) {
    ticks.emplace_back(decadeLabel(firstExponent + k, false),
                       transform(linearWithin * std::pow(10.0, k)));
  }
  const double low = (negativeDecades > 0 ? ticks.front().second : -0.5) - 0.15;
  const double high = ticks.back().second + 0.15;
  yAxis->setStartValue(low);
  for (const auto& [label, value] : ticks)
    yAxis->append(label, value);
  yAxis->setRange(low, high);
  yAxis->setGridLineVisible(true);

  auto* chart = new QChart;
  chart->setTitle(relative ? "Energy residual: E(t) − E(0) − work + drag, relative to |E(0)|"
                           : "Energy residual: E(t) − E(0) − work + drag (J)");
  chart->legend()->setAlignment(Qt::AlignBottom);
  QValueAxis* xAxis = timeAxis(data.duration);
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  for (std::size_t run = 0; run < data.curves.size(); ++run) {
    const CompareCurve& curve = data.curves[run];
    QLineSeries* line = curveSeries(curve, run);
    for (std::size_t i = 0; i < curve.times.size(); ++i) {
      const double r = plotted(curve, i);
      if (std::isfinite(r)) line->append(curve.times[i], transform(r));
    }
    addSeries(chart, line, xAxis, yAxis, true);
  }
  return chart;
}

}  // namespace

void saveCompareChart(const CompareChart& chart, const std::filesystem::path& path) {
  const OffscreenQt qt;
  if (chart.curves.empty()) throw std::invalid_argument("compare chart: no runs to draw");
  const std::vector<QChart*> charts = {divergencePanel(chart), residualPanel(chart)};
  saveCharts(charts, QString::fromStdString(chart.title), 760, 620, path);
}

}  // namespace fooball::plots
