#pragma once

#include <filesystem>
#include <span>

#include "capacity.h"

namespace fooball::plots {

/// `capacity --chart`: every backend's median step against ball count on log–log axes (the
/// counts the search measured), the budget as a horizontal line, and each backend's capacity
/// marked and named in the legend. Throws std::runtime_error when the PNG cannot be written.
void saveCapacityChart(std::span<const measure::CapacityResult> results,
                       const measure::CapacitySettings& settings,
                       const std::filesystem::path& path);

}  // namespace fooball::plots
