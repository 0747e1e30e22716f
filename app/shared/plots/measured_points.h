#pragma once

#include <QPointF>
#include <cstddef>
#include <optional>
#include <vector>

class QXYSeries;

namespace fooball::plots {

/// A chart whose points stand for measurements (a tradeoff setting, a sweep's scene) tags each
/// series that draws them with the measurement behind each of its points: `indices[i]` is the
/// index, into the measurements the chart was made from, of the series' i-th point.
void tagMeasurements(QXYSeries& series, const std::vector<std::size_t>& indices);

/// The measurement behind the point of `series` nearest `clicked` (in the axes' values, as
/// QXYSeries::clicked gives it), measured in pixels on the chart; none for a series without
/// measurements (a threshold line).
std::optional<std::size_t> measurementAt(const QXYSeries& series, QPointF clicked);

}  // namespace fooball::plots
