#include "capacity_command.h"

#include <fstream>
#include <stdexcept>

#include "capacity.h"
#include "capacity_chart.h"
#include "chosen_backends.h"
#include "progress_line.h"
#include "readable_number.h"
#include "registry.h"
#include "run_setup.h"
#include "status_line.h"
#include "text_table.h"
#include "usage_error.h"

namespace fooball::cli {

namespace {

measure::CapacitySettings settingsFrom(const CapacityOptions& options) {
  measure::CapacitySettings settings;
  settings.budgetMs = options.budgetMs;
  settings.packingFraction = options.packingFraction;
  settings.warmUpSeconds = options.warmUpSeconds;
  settings.timedSteps = options.steps;
  settings.options = options.assignments;
  settings.limits.timeLimitSeconds = options.timeLimitSeconds;
  return settings;
}

void printTable(const std::vector<measure::CapacityResult>& results,
                const measure::CapacitySettings& settings, std::ostream& out) {
  out << "Capacity: the most balls whose median step fits "
      << text::readableText(settings.budgetMs, 4) << " ms\n(standard gas at packing fraction "
      << text::readableText(settings.packingFraction)
      << ", one step = " << text::readableText(settings.dt, 4) << " s, median of "
      << settings.timedSteps << " steps after " << measure::stepTimingOf(settings).warmUpSteps
      << " untimed ones to thermalise; default options";
  for (const std::string& option : settings.options)
    out << ", " << option;
  out << ")\n\n";
  TextTable table;
  table.addRow({"backend", "balls", "median step", "counts measured", "note"});
  for (const measure::CapacityResult& result : results) {
    table.addRow({result.backend, std::to_string(result.outcome.balls),
                  text::readableText(result.outcome.medianStepMs, 4) + " ms",
                  std::to_string(result.outcome.probes.size()), measure::capacityNote(result)});
  }
  table.print(out, 2);
}

}  // namespace

void capacityCommand(const CapacityOptions& options, std::ostream& out) {
  const std::vector<RunSpec> runs = chosenRuns(options.backends);
  const measure::CapacitySettings settings = settingsFrom(options);
  if (!(options.timeLimitSeconds > 0.0)) throw UsageError("--time-limit: must be > 0");
  measure::checkCapacitySettings(runs, settings);
  if (options.csvPath) checkWritableFile(*options.csvPath, "--csv");
  if (options.chartPath) checkWritableFile(*options.chartPath, "--chart");

  StatusLine status(!options.quiet && ProgressLine::stderrIsTerminal());
  const auto progress = [&](const measure::CapacityProgress& at) {
    status.show(text::readableText(100.0 * at.fraction, 3) + "%  " + std::string(at.backend) +
                ": " + std::to_string(at.search.latest.balls) + " balls, median step " +
                text::readableText(at.search.latest.medianStepMs, 3) + " ms");
  };
  const std::vector<measure::CapacityResult> results =
      measure::measureCapacity(runs, settings, progress);
  status.clear();

  if (!options.quiet) printTable(results, settings, out);
  if (options.csvPath) {
    std::ofstream csv(*options.csvPath);
    measure::writeCapacityCsv(csv, results);
    csv.close();
    if (!csv) throw std::runtime_error(options.csvPath->string() + ": cannot write the CSV file");
  }
  if (options.chartPath) plots::saveCapacityChart(results, settings, *options.chartPath);
}

}  // namespace fooball::cli
