#pragma once

#include <QString>
#include <span>
#include <vector>

#include "failure_map.h"

class QChart;

namespace fooball::plots {

/// The panels of one sweep's `failure-map --chart-dir` PNG and of the app's Tools → Failure
/// map: the error against the parameter and, for a sweep with an overlap limit, the deepest
/// overlap. Each curve is tagged with the index into `points` of each of its points
/// (measured_points.h). The caller owns the charts. Needs a QApplication.
std::vector<QChart*> makeFailureMapCharts(const failure_map::SweepSpec& spec,
                                          std::span<const failure_map::SweepPoint> points);

/// The charts' heading: the sweep and what it does.
QString failureMapChartTitle(const failure_map::SweepSpec& spec);

}  // namespace fooball::plots
