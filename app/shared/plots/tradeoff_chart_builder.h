#pragma once

#include <QString>
#include <span>
#include <string>
#include <vector>

#include "tradeoff.h"

class QChart;

namespace fooball::plots {

/// The two panels of `tradeoff --chart` and of the app's Tools → Speed vs accuracy: CPU cost
/// against the trajectory error, then against the energy error. Each backend's scatter series
/// is tagged with the index into `points` of each of its points (measured_points.h). The caller
/// owns the charts. Needs a QApplication.
std::vector<QChart*> makeTradeoffCharts(std::span<const measure::TradeoffPoint> points,
                                        const measure::TradeoffSettings& settings);

/// The charts' heading, for `scene` (how it is named, e.g. "'gas' (40 balls)").
QString tradeoffChartTitle(const std::string& scene, const measure::TradeoffSettings& settings);

}  // namespace fooball::plots
