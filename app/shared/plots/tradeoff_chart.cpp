#include "tradeoff_chart.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <algorithm>
#include <cmath>
#include <limits>

#include "chart_image.h"
#include "measured_points.h"
#include "offscreen_qt.h"
#include "pareto.h"
#include "run_palette.h"
#include "tradeoff_chart_builder.h"

namespace fooball::plots {

namespace {

/// One panel's error: which field, how the axis names it.
struct ErrorAxis {
  double measure::TradeoffPoint::*error;
  QString title;
};

/// The backends in the order their points first appear.
std::vector<std::string> backendsOf(std::span<const measure::TradeoffPoint> points) {
  std::vector<std::string> backends;
  for (const measure::TradeoffPoint& point : points) {
    if (std::find(backends.begin(), backends.end(), point.setting.backend) == backends.end())
      backends.push_back(point.setting.backend);
  }
  return backends;
}

QChart* panel(std::span<const measure::TradeoffPoint> points, const ErrorAxis& axis) {
  // Zero errors sit a decade below the smallest non-zero one: a log axis has no 0.
  double leastError = std::numeric_limits<double>::infinity();
  double mostError = 0.0;
  double leastCost = std::numeric_limits<double>::infinity();
  double mostCost = 0.0;
  for (const measure::TradeoffPoint& point : points) {
    const double error = point.*axis.error;
    if (error > 0.0) leastError = std::min(leastError, error);
    mostError = std::max(mostError, error);
    leastCost = std::min(leastCost, point.cpuMsPerSimulatedSecond);
    mostCost = std::max(mostCost, point.cpuMsPerSimulatedSecond);
  }
  // Every error zero (an exact method on a simple scene): any decade will do for the bottom row.
  if (!std::isfinite(leastError)) leastError = 1.0;
  const double zeroAt = decadeBelow(leastError) / 10.0;
  if (!std::isfinite(leastCost)) leastCost = mostCost = 1.0;
  const auto shown = [&](double error) { return error > 0.0 ? error : zeroAt; };

  // The legend beside the plot: in a row under it, Qt shortens every entry to "…" once the
  // backends' names do not fit the panel's width.
  auto* chart = new QChart;
  chart->legend()->setAlignment(Qt::AlignRight);
  QLogValueAxis* xAxis = decadeAxis("CPU ms per simulated second", leastCost, mostCost, "%.0e");
  QLogValueAxis* yAxis = decadeAxis(axis.title, zeroAt, std::max(mostError, zeroAt), "%.0e");
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  const auto add = [&](QAbstractSeries* series, bool inLegend) {
    addSeries(chart, series, xAxis, yAxis, inLegend);
  };

  for (const std::string& backend : backendsOf(points)) {
    auto* scatter = new QScatterSeries;
    const bool allZero = std::all_of(points.begin(), points.end(), [&](const auto& point) {
      return point.setting.backend != backend || point.*axis.error == 0.0;
    });
    scatter->setName(QString::fromStdString(backend) +
                     (allZero ? " (error 0: at the bottom)" : ""));
    scatter->setColor(colours::backendColour(backend));
    scatter->setMarkerSize(9.0);
    std::vector<measure::CostAndError> own;
    std::vector<std::size_t> measured;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const measure::TradeoffPoint& point = points[i];
      if (point.setting.backend != backend) continue;
      scatter->append(point.cpuMsPerSimulatedSecond, shown(point.*axis.error));
      own.push_back({point.cpuMsPerSimulatedSecond, point.*axis.error});
      measured.push_back(i);
    }
    tagMeasurements(*scatter, measured);
    add(scatter, true);
    // The front is drawn over its points and takes their clicks: it opens them as they would.
    auto* front = new QLineSeries;
    front->setPen(QPen(colours::backendColour(backend), 2.0));
    std::vector<std::size_t> onFront;
    for (const std::size_t i : measure::paretoFront(own)) {
      front->append(own[i].cost, shown(own[i].error));
      onFront.push_back(measured[i]);
    }
    tagMeasurements(*front, onFront);
    add(front, false);
  }
  return chart;
}

}  // namespace

std::vector<QChart*> makeTradeoffCharts(std::span<const measure::TradeoffPoint> points,
                                        const measure::TradeoffSettings& settings) {
  // On two lines: a title up the side of a plot longer than its height is cut at both ends.
  const QString trajectory = QString("RMS distance from %1<br>at %2 s (m)")
                                 .arg(QString::fromUtf8(measure::kReferenceBackend))
                                 .arg(settings.compareAt);
  const QString energy =
      QString("largest energy error<br>in %1 s (relative)").arg(settings.duration);
  return {panel(points, {&measure::TradeoffPoint::trajectoryError, trajectory}),
          panel(points, {&measure::TradeoffPoint::energyError, energy})};
}

QString tradeoffChartTitle(const std::string& scene, const measure::TradeoffSettings& settings) {
  return QString("Speed against accuracy on %1 (dt %2 s; lines: Pareto fronts)")
      .arg(QString::fromStdString(scene))
      .arg(settings.dt, 0, 'g', 4);
}

void saveTradeoffChart(std::span<const measure::TradeoffPoint> points, const std::string& scene,
                       const measure::TradeoffSettings& settings,
                       const std::filesystem::path& path) {
  const OffscreenQt qt;
  saveCharts(makeTradeoffCharts(points, settings), tradeoffChartTitle(scene, settings), 720, 600,
             path);
}

}  // namespace fooball::plots
