#pragma once

#include <filesystem>
#include <span>

#include "failure_map.h"

namespace fooball::plots {

/// `failure-map --chart-dir`: one PNG for one sweep. Left, its error metric against its
/// parameter on log–log axes, one line per backend and variant (colour: backend; dash: variant),
/// failing points ringed, the threshold as a dashed red line; right, for sweeps with an overlap
/// limit, the deepest overlap the same way. Errors of 0 are drawn at the bottom of the axis.
/// Throws std::runtime_error when the PNG cannot be written.
void saveFailureMapChart(const failure_map::SweepSpec& spec,
                         std::span<const failure_map::SweepPoint> points,
                         const std::filesystem::path& path);

}  // namespace fooball::plots
