#pragma once

#include <filesystem>
#include <string>

#include "csv_file.h"
#include "fooball/metrics.h"

namespace fooball::cli {

/// The `run --metrics` file: a header, then one row per Metrics, doubles in round-trip text.
class MetricsCsv {
 public:
  /// The header, exactly as DESIGN.md ("fooball-cli (headless)") orders the columns.
  static constexpr const char* kHeader =
      "time,kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y,ball_collisions,"
      "wall_collisions,wall_impulse,max_overlap,escaped";

  /// Creates (truncates) `path` and writes the header; throws UsageError naming the path and
  /// the reason when it cannot be opened, so a bad path fails before any simulation.
  explicit MetricsCsv(const std::filesystem::path& path);

  void writeRow(const Metrics& metrics);

  /// Flushes and closes; throws std::runtime_error when the data did not reach the file.
  void close();

 private:
  CsvFile file_;
  std::string row_;  ///< reused for every row
};

}  // namespace fooball::cli
