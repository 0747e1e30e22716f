#include "tradeoff_command.h"

#include <fstream>
#include <stdexcept>

#include "chosen_backends.h"
#include "fooball/presets.h"
#include "fooball/scene_file.h"
#include "progress_line.h"
#include "readable_number.h"
#include "run_setup.h"
#include "status_line.h"
#include "text_table.h"
#include "tradeoff.h"
#include "tradeoff_chart.h"

namespace fooball::cli {

namespace {

void printTable(const std::vector<measure::TradeoffPoint>& points, const Scene& scene,
                const measure::TradeoffSettings& settings, double chaosGrowth, std::ostream& out) {
  out << "Speed against accuracy on '" << scene.name << "' (" << scene.balls.size()
      << " balls): " << text::readableText(settings.duration) << " s at dt "
      << text::readableText(settings.dt, 4) << " s per setting; positions compared with the exact "
      << "backend's at " << text::readableText(settings.compareAt) << " s, by when the scene "
      << "amplifies a difference " << text::readableText(chaosGrowth, 2) << "-fold.\n"
      << "Errors: energy and momentum relative, overlap as a fraction of the smaller radius, "
         "trajectory as RMS distance in m. *: on the backend's Pareto front of CPU cost against "
         "trajectory error.\n\n";
  const std::vector<bool> front =
      measure::onFront(points, &measure::TradeoffPoint::trajectoryError);
  TextTable table;
  table.addRow({"", "backend", "settings", "CPU ms/sim s", "energy err", "momentum err",
                "max overlap", "trajectory err (m)"});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const measure::TradeoffPoint& point = points[i];
    table.addRow(
        {front[i] ? "*" : "", point.setting.backend, measure::settingsText(point.setting),
         text::readableText(point.cpuMsPerSimulatedSecond, 3),
         text::readableText(point.energyError, 2), text::readableText(point.momentumError, 2),
         text::readableText(point.maxOverlap, 2), text::readableText(point.trajectoryError, 2)});
  }
  table.print(out, 2);
}

}  // namespace

void tradeoffCommand(const TradeoffOptions& options, std::ostream& out) {
  const Scene scene =
      options.scenePath ? loadSceneFile(*options.scenePath) : loadPreset(options.presetName);
  measure::TradeoffSettings settings;
  settings.duration = options.duration;
  settings.compareAt = options.compareAt;
  const std::vector<measure::TradeoffSetting> grid =
      measure::tradeoffGrid(chosenBackends(options.backends));
  if (options.csvPath) checkWritableFile(*options.csvPath, "--csv");
  if (options.chartPath) checkWritableFile(*options.chartPath, "--chart");

  StatusLine status(!options.quiet && ProgressLine::stderrIsTerminal());
  const auto progress = [&](const measure::TradeoffProgress& at) {
    status.show(text::readableText(100.0 * at.fraction, 3) + "%  " + at.setting->backend + " " +
                measure::settingsText(*at.setting));
  };
  const std::vector<measure::TradeoffPoint> points =
      measure::measureTradeoff(scene, grid, settings, progress);
  const double chaosGrowth = measure::chaosGrowth(scene, settings);
  status.clear();

  if (!options.quiet) printTable(points, scene, settings, chaosGrowth, out);
  if (options.csvPath) {
    std::ofstream csv(*options.csvPath);
    measure::writeTradeoffCsv(csv, points);
    csv.close();
    if (!csv) throw std::runtime_error(options.csvPath->string() + ": cannot write the CSV file");
  }
  if (options.chartPath) {
    const std::string title =
        "'" + scene.name + "' (" + std::to_string(scene.balls.size()) + " balls)";
    plots::saveTradeoffChart(points, title, settings, *options.chartPath);
  }
}

}  // namespace fooball::cli
