#include "failure_map_command.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "boundary.h"
#include "chosen_backends.h"
#include "failure_map.h"
#include "failure_map_chart.h"
#include "fooball/number_text.h"
#include "progress_line.h"
#include "readable_number.h"
#include "run_setup.h"
#include "status_line.h"
#include "text_table.h"
#include "usage_error.h"

namespace fooball::cli {

namespace {

using failure_map::Boundary;
using failure_map::SweepPoint;
using failure_map::SweepSpec;

/// The columns of `failure-map --csv`, one row per point.
constexpr const char* kCsvHeader =
    "sweep,backend,variant,parameter_name,parameter,error_name,error,max_overlap,passed";

std::vector<const SweepSpec*> chosenSweeps(const std::vector<std::string>& names) {
  std::vector<const SweepSpec*> chosen;
  if (names.empty()) {
    for (const SweepSpec& spec : failure_map::sweepSpecs())
      chosen.push_back(&spec);
  }
  for (const std::string& name : names)
    chosen.push_back(&failure_map::findSweep(name));  // throws for an unknown name
  return chosen;
}

/// "passes up to 2.4, fails from 2.8", read from the easy end of the parameter to the hard one.
std::string boundaryText(const SweepSpec& spec, const Boundary& boundary) {
  const std::string direction = spec.harderAbove ? "up to " : "down to ";
  if (!boundary.firstFail)
    return "passes everywhere tested (" + direction + text::readableText(*boundary.lastPass, 3) +
           ")";
  std::string text =
      boundary.lastPass
          ? "passes " + direction + text::readableText(*boundary.lastPass, 3) + ", fails from " +
                text::readableText(*boundary.firstFail, 3)
          : "fails everywhere tested (from " + text::readableText(*boundary.firstFail, 3) + ")";
  if (boundary.passesAgain) text += "; passes again at some harder points";
  return text;
}

void printSweep(const SweepSpec& spec, const std::vector<SweepPoint>& points, TextTable& table) {
  table.addLine(std::string(spec.name) + ": " + std::string(spec.title) +
                ". Parameter: " + std::string(spec.parameterName) + ".");
  std::string limits =
      "  fails when " + std::string(spec.errorName) + " > " + text::readableText(spec.threshold, 3);
  if (std::isfinite(spec.overlapLimit))
    limits += " or the deepest overlap > " + text::readableText(spec.overlapLimit, 3) + " r";
  table.addLine(limits);
  for (const Boundary& boundary : failure_map::locateBoundaries(spec, points))
    table.addRow({boundary.backend, boundary.variant, boundaryText(spec, boundary)});
  table.addLine("");
}

void writeCsv(const std::filesystem::path& path, const std::vector<SweepPoint>& points) {
  std::ofstream csv(path);
  csv << kCsvHeader << '\n';
  for (const SweepPoint& point : points) {
    const SweepSpec& spec = failure_map::findSweep(point.sweep);
    csv << point.sweep << ',' << point.backend << ',' << point.variant << ',' << spec.parameterName
        << ',' << exactNumberText(point.parameter) << ',' << spec.errorName << ','
        << exactNumberText(point.error) << ',' << exactNumberText(point.maxOverlap) << ','
        << (point.passed ? "pass" : "fail") << '\n';
  }
  csv.close();
  if (!csv) throw std::runtime_error(path.string() + ": cannot write the CSV file");
}

}  // namespace

void failureMapCommand(const FailureMapOptions& options, std::ostream& out) {
  const std::vector<BackendInfo> backends = chosenBackends(options.backends);
  const std::vector<const SweepSpec*> sweeps = chosenSweeps(options.sweeps);
  if (options.csvPath) checkWritableFile(*options.csvPath, "--csv");
  if (options.chartDir && !std::filesystem::is_directory(*options.chartDir)) {
    throw UsageError("--chart-dir '" + options.chartDir->string() + "': no such directory");
  }

  StatusLine status(!options.quiet && ProgressLine::stderrIsTerminal());
  const auto progress = [&](const failure_map::FailureMapProgress& at) {
    status.show(std::string(at.sweep->name) + " on " + std::string(at.backend));
  };
  const std::vector<SweepPoint> all =
      failure_map::runFailureMap(sweeps, backends, options.quick, progress);
  status.clear();
  TextTable table;
  for (const SweepSpec* spec : sweeps) {
    std::vector<SweepPoint> points;
    std::copy_if(all.begin(), all.end(), std::back_inserter(points),
                 [&](const SweepPoint& point) { return point.sweep == spec->name; });
    printSweep(*spec, points, table);
    if (options.chartDir) {
      plots::saveFailureMapChart(
          *spec, points, *options.chartDir / ("failure-" + std::string(spec->name) + ".png"));
    }
  }
  if (!options.quiet) table.print(out, 2);
  if (options.csvPath) writeCsv(*options.csvPath, all);
}

}  // namespace fooball::cli
