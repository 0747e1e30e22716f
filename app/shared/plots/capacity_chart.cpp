#include "capacity_chart.h"

#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <algorithm>
#include <cmath>
#include <limits>

#include "capacity_chart_builder.h"
#include "chart_image.h"
#include "offscreen_qt.h"
#include "run_palette.h"

namespace fooball::plots {

namespace {

QString countText(std::size_t balls) {
  if (balls >= 10'000)
    return QString::number(std::round(static_cast<double>(balls) / 1000.0)) + "k";
  return QString::number(balls);
}

}  // namespace

QChart* makeCapacityChart(std::span<const measure::CapacityResult> results,
                          const measure::CapacitySettings& settings) {
  // The legend beside the plot: in a row under it, Qt shortened the entries ("box2d: 5250…").
  auto* chart = new QChart;
  chart->legend()->setAlignment(Qt::AlignRight);

  double leastBalls = std::numeric_limits<double>::infinity();
  double mostBalls = 1.0;
  double leastMs = settings.budgetMs;
  double mostMs = settings.budgetMs;
  std::vector<QAbstractSeries*> series;
  for (const measure::CapacityResult& result : results) {
    std::vector<measure::Probe> probes = result.outcome.probes;
    std::sort(probes.begin(), probes.end(),
              [](const measure::Probe& a, const measure::Probe& b) { return a.balls < b.balls; });
    auto* cost = new QLineSeries;
    cost->setName(QString::fromStdString(result.backend) + ": " + countText(result.outcome.balls) +
                  " balls");
    cost->setColor(colours::backendColour(result.backend));
    cost->setPointsVisible(true);
    cost->setMarkerSize(5.0);
    for (const measure::Probe& probe : probes) {
      const double ms = std::max(probe.medianStepMs, 1e-4);  // a log axis has no 0
      cost->append(static_cast<double>(probe.balls), ms);
      leastBalls = std::min(leastBalls, static_cast<double>(probe.balls));
      mostBalls = std::max(mostBalls, static_cast<double>(probe.balls));
      leastMs = std::min(leastMs, ms);
      mostMs = std::max(mostMs, ms);
    }
    series.push_back(cost);
    if (result.outcome.balls > 0) {
      auto* capacity = new QScatterSeries;
      capacity->setColor(colours::backendColour(result.backend));
      capacity->setBorderColor(Qt::black);
      capacity->setMarkerSize(12.0);
      capacity->append(static_cast<double>(result.outcome.balls), result.outcome.medianStepMs);
      series.push_back(capacity);
    }
  }
  if (!std::isfinite(leastBalls)) leastBalls = 1.0;

  auto* budget = new QLineSeries;
  budget->setName(QString("budget %1 ms").arg(settings.budgetMs, 0, 'g', 4));
  budget->setColor(Qt::darkRed);
  budget->setPen(QPen(Qt::darkRed, 1.5, Qt::DashLine));
  budget->append(decadeBelow(leastBalls), settings.budgetMs);
  budget->append(decadeAbove(mostBalls), settings.budgetMs);
  series.push_back(budget);

  QLogValueAxis* xAxis = decadeAxis("balls (standard gas)", leastBalls, mostBalls, "%g");
  QLogValueAxis* yAxis = decadeAxis("median step (ms)", leastMs, mostMs, "%g");
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  for (QAbstractSeries* one : series) {
    chart->addSeries(one);
    one->attachAxis(xAxis);
    one->attachAxis(yAxis);
  }
  // The capacity markers repeat their backend's colour: only the cost lines need a legend entry.
  for (QAbstractSeries* one : series) {
    if (one->type() == QAbstractSeries::SeriesTypeScatter) {
      for (QLegendMarker* marker : chart->legend()->markers(one))
        marker->setVisible(false);
    }
  }

  return chart;
}

QString capacityChartTitle(const measure::CapacitySettings& settings) {
  QString options;
  for (const std::string& option : settings.options)
    options += ", " + QString::fromStdString(option);
  return QString(
             "Capacity: the most balls whose median step fits %1 ms "
             "(standard gas at packing fraction %2, dt %3 s%4)")
      .arg(settings.budgetMs, 0, 'g', 4)
      .arg(settings.packingFraction)
      .arg(settings.dt, 0, 'g', 4)
      .arg(options);
}

void saveCapacityChart(std::span<const measure::CapacityResult> results,
                       const measure::CapacitySettings& settings,
                       const std::filesystem::path& path) {
  const OffscreenQt qt;
  saveCharts({makeCapacityChart(results, settings)}, capacityChartTitle(settings), 1000, 640, path);
}

}  // namespace fooball::plots
