#pragma once

#include <QString>
#include <span>

#include "capacity.h"

class QChart;

namespace fooball::plots {

/// The chart of `capacity --chart` and of the app's Tools → Benchmark: every backend's median
/// step against ball count on log–log axes (the counts the search measured), the budget as a
/// horizontal line, and each backend's capacity marked and named in the legend. The caller owns
/// the chart (a QChartView takes it over). Needs a QApplication.
QChart* makeCapacityChart(std::span<const measure::CapacityResult> results,
                          const measure::CapacitySettings& settings);

/// The chart's heading: the budget and how the search measured.
QString capacityChartTitle(const measure::CapacitySettings& settings);

}  // namespace fooball::plots
