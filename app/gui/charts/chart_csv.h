#pragma once

#include <QString>

#include "chart_data.h"

namespace fooball::gui {

/// The CSV header: the run's name, then the charted quantities in SI units (J, N·s, m; the
/// relative residual has none), names and order following `fooball-cli run --metrics` and
/// `fooball-cli compare` (the position differences are from run 0, so run 0's are 0).
inline constexpr const char* kChartCsvHeader =
    "run,time,kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y,"
    "momentum_magnitude,energy_residual,relative_energy_residual,rms_position_difference,"
    "max_position_difference";

/// The `run` field of the chaos baseline's rows, as `fooball-cli compare --baseline` writes it.
inline constexpr const char* kBaselineCsvRun = "baseline";

/// Writes the header and one row per stored sample per run (run 0's rows, then run 1's, …, then
/// the shown baseline's), with numbers in round-trip text; an undefined value (the relative
/// residual when E₀ = 0) is an empty field. Replaces `path` only when everything was written;
/// false when that failed.
bool writeChartCsv(const QString& path, const ChartData& data);

}  // namespace fooball::gui
