#include "measured_points.h"

#include <QChart>
#include <QVariant>
#include <QXYSeries>
#include <limits>

namespace fooball::plots {

namespace {

constexpr const char* kMeasurementsProperty = "fooballMeasurements";

}  // namespace

void tagMeasurements(QXYSeries& series, const std::vector<std::size_t>& indices) {
  QVariantList list;
  for (const std::size_t index : indices)
    list.append(QVariant::fromValue(qulonglong(index)));
  series.setProperty(kMeasurementsProperty, list);
}

std::optional<std::size_t> measurementAt(const QXYSeries& series, QPointF clicked) {
  const QVariantList indices = series.property(kMeasurementsProperty).toList();
  const QList<QPointF> points = series.points();
  if (indices.size() != points.size()) return std::nullopt;
  // Pixels, not values: on log axes a decade is as wide at 1e-9 as at 1.
  QChart* chart = series.chart();
  auto* drawn = const_cast<QXYSeries*>(&series);  // mapToPosition takes a non-const series
  const auto position = [&](QPointF value) {
    return chart ? chart->mapToPosition(value, drawn) : value;
  };
  const QPointF at = position(clicked);
  std::optional<std::size_t> nearest;
  double nearestDistance = std::numeric_limits<double>::infinity();
  for (qsizetype i = 0; i < points.size(); ++i) {
    const QPointF offset = position(points[i]) - at;
    const double distance = QPointF::dotProduct(offset, offset);
    if (distance < nearestDistance) {
      nearestDistance = distance;
      nearest = static_cast<std::size_t>(indices[i].toULongLong());
    }
  }
  return nearest;
}

}  // namespace fooball::plots
