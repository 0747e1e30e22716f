#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "tradeoff.h"

namespace fooball::plots {

/// `tradeoff --chart`, for `scene` (how the title names it): two log–log scatter plots side by
/// side, CPU cost per simulated second against the trajectory error and against the energy error,
/// each backend's points in its colour and its Pareto front joined by a line. Errors of 0 (the
/// exact backend against itself) are drawn at the bottom of the axis. Throws
/// std::runtime_error when the PNG cannot be written.
void saveTradeoffChart(std::span<const measure::TradeoffPoint> points, const std::string& scene,
                       const measure::TradeoffSettings& settings,
                       const std::filesystem::path& path);

}  // namespace fooball::plots
