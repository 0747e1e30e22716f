#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "csv_file.h"
#include "fooball/divergence.h"
#include "fooball/metrics.h"

namespace fooball::cli {

/// The `compare --csv` file: a header, then one row per run per sample, doubles in round-trip
/// text (exactNumberText).
class CompareCsv {
 public:
  /// The header, exactly as DESIGN.md ("fooball-cli (headless)") orders the columns.
  static constexpr const char* kHeader =
      "time,run,kinetic_energy,total_energy,momentum_x,momentum_y,energy_residual,"
      "rms_position_difference,max_position_difference";

  /// Creates (truncates) `path` and writes the header; throws UsageError naming the path and
  /// the reason when it cannot be opened, so a bad path fails before any simulation.
  explicit CompareCsv(const std::filesystem::path& path);

  /// One run's row: `run` is its label (the spec text, or "baseline"), `fromReference` its
  /// divergence from run 0.
  void writeRow(std::string_view run, const Metrics& metrics, const Divergence& fromReference);

  /// Flushes and closes; throws std::runtime_error when the data did not reach the file.
  void close();

 private:
  CsvFile file_;
  std::string row_;  ///< reused for every row
};

}  // namespace fooball::cli
