#include "failure_map_chart.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "chart_image.h"
#include "failure_map_chart_builder.h"
#include "measured_points.h"
#include "offscreen_qt.h"
#include "run_palette.h"

namespace fooball::plots {

namespace {

using failure_map::SweepPoint;
using failure_map::SweepSpec;

/// One panel's quantity: which field, how the axis names it, where it starts to fail.
struct Measure {
  double SweepPoint::*field;
  QString title;
  double limit;
  double floor;  ///< values below are drawn here; 0: a decade under the smallest non-zero one
};

/// The curves of `points`, each (backend, variant) once, in the order they first appear.
std::vector<std::pair<std::string, std::string>> curvesOf(std::span<const SweepPoint> points) {
  std::vector<std::pair<std::string, std::string>> curves;
  for (const SweepPoint& point : points) {
    const std::pair<std::string, std::string> curve{point.backend, point.variant};
    if (std::find(curves.begin(), curves.end(), curve) == curves.end()) curves.push_back(curve);
  }
  return curves;
}

/// The variants in the order they first appear: each gets its own line style.
Qt::PenStyle variantStyle(std::span<const SweepPoint> points, const std::string& variant) {
  std::vector<std::string> variants;
  for (const SweepPoint& point : points) {
    if (std::find(variants.begin(), variants.end(), point.variant) == variants.end())
      variants.push_back(point.variant);
  }
  static const Qt::PenStyle kStyles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
  const auto index = static_cast<std::size_t>(std::find(variants.begin(), variants.end(), variant) -
                                              variants.begin());
  return kStyles[std::min(index, std::size(kStyles) - 1)];
}

QChart* panel(const SweepSpec& spec, std::span<const SweepPoint> points, const Measure& measure) {
  // Zero values sit at the floor: a log axis has no 0.
  double least = measure.limit;
  double most = 10.0 * measure.limit;  // the threshold line below the top of the axis
  double leastParameter = std::numeric_limits<double>::infinity();
  double mostParameter = 0.0;
  for (const SweepPoint& point : points) {
    const double value = point.*measure.field;
    if (value > 0.0 && std::isfinite(value)) {
      least = std::min(least, value);
      most = std::max(most, value);
    }
    leastParameter = std::min(leastParameter, point.parameter);
    mostParameter = std::max(mostParameter, point.parameter);
  }
  const double zeroAt = measure.floor > 0.0 ? measure.floor : decadeBelow(least) / 10.0;
  const auto shown = [&](double value) {
    return std::isfinite(value) ? std::max(value, zeroAt) : most;  // NaN/inf: at the top
  };

  auto* chart = new QChart;
  chart->legend()->setAlignment(Qt::AlignRight);
  const QString parameterTitle = QString::fromStdString(std::string(spec.parameterName));
  QAbstractAxis* xAxis = nullptr;
  double xFrom = 0.0;  // where the threshold line starts and ends
  double xTo = 1.0;
  if (spec.logParameter) {
    xAxis = decadeAxis(parameterTitle, leastParameter, mostParameter, "%g");
    xFrom = decadeBelow(leastParameter);
    xTo = decadeAbove(mostParameter);
  } else {
    // Fractions: a linear axis from 0 to 1.
    auto* linear = new QValueAxis;
    linear->setTitleText(parameterTitle);
    linear->setRange(0.0, 1.0);
    linear->setTickCount(11);
    linear->setLabelFormat("%.1f");
    xAxis = linear;
  }
  QLogValueAxis* yAxis = decadeAxis(measure.title, zeroAt, most, "%.0e");
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  const auto add = [&](QAbstractSeries* series, bool inLegend) {
    addSeries(chart, series, xAxis, yAxis, inLegend);
  };

  auto* limit = new QLineSeries;
  limit->setName(QString("fails above %1").arg(measure.limit, 0, 'g', 3));
  limit->setPen(QPen(QColor(0xd0, 0x30, 0x30), 1.5, Qt::DashLine));
  limit->append(xFrom, measure.limit);
  limit->append(xTo, measure.limit);
  add(limit, true);

  auto* failing = new QScatterSeries;
  failing->setName("failing point");
  failing->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  failing->setMarkerSize(11.0);
  failing->setColor(Qt::transparent);
  failing->setBorderColor(QColor(0xd0, 0x30, 0x30));
  // The circles are drawn over the curves' points and take their clicks: they open them too.
  std::vector<std::size_t> failingMeasured;
  for (const auto& [backend, variant] : curvesOf(points)) {
    auto* line = new QLineSeries;
    line->setName(QString::fromStdString(variant.empty() ? backend : backend + ", " + variant));
    line->setPen(QPen(colours::backendColour(backend), 2.0, variantStyle(points, variant)));
    line->setPointsVisible(true);
    std::vector<const SweepPoint*> curve;
    for (const SweepPoint& point : points) {
      if (point.backend == backend && point.variant == variant) curve.push_back(&point);
    }
    std::sort(curve.begin(), curve.end(),
              [](const SweepPoint* a, const SweepPoint* b) { return a->parameter < b->parameter; });
    std::vector<std::size_t> measured;
    for (const SweepPoint* point : curve) {
      line->append(point->parameter, shown(point->*measure.field));
      measured.push_back(static_cast<std::size_t>(point - points.data()));
      if (!(point->*measure.field <= measure.limit)) {
        failing->append(point->parameter, shown(point->*measure.field));
        failingMeasured.push_back(measured.back());
      }
    }
    tagMeasurements(*line, measured);
    add(line, true);
  }
  tagMeasurements(*failing, failingMeasured);
  add(failing, true);
  return chart;
}

}  // namespace

std::vector<QChart*> makeFailureMapCharts(const SweepSpec& spec,
                                          std::span<const SweepPoint> points) {
  std::vector<QChart*> charts = {
      panel(spec, points,
            {&SweepPoint::error, QString::fromStdString(std::string(spec.errorName)),
             spec.threshold, 0.0})};
  if (std::isfinite(spec.overlapLimit)) {
    charts.push_back(
        panel(spec, points,
              {&SweepPoint::maxOverlap, "deepest overlap (fraction of r; below 1e-4 at the bottom)",
               spec.overlapLimit, 1e-4}));
  }
  return charts;
}

QString failureMapChartTitle(const SweepSpec& spec) {
  return QString("Failure map, %1: %2 (errors of 0 drawn at the bottom)")
      .arg(QString::fromStdString(std::string(spec.name)),
           QString::fromStdString(std::string(spec.title)));
}

void saveFailureMapChart(const SweepSpec& spec, std::span<const SweepPoint> points,
                         const std::filesystem::path& path) {
  const OffscreenQt qt;
  saveCharts(makeFailureMapCharts(spec, points), failureMapChartTitle(spec), 900, 600, path);
}

}  // namespace fooball::plots
