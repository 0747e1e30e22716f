#include "compare_command.h"

#include <chrono>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compare_chart.h"
#include "compare_csv.h"
#include "compare_summary.h"
#include "fooball/run_group.h"
#include "fooball/run_spec.h"
#include "progress_line.h"
#include "readable_number.h"
#include "registry.h"
#include "run_setup.h"
#include "run_warnings.h"
#include "usage_error.h"

namespace fooball::cli {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kMinRuns = 2;
/// The chart needs no more points per curve than it has pixels across.
constexpr std::uint64_t kMaxChartPoints = 2000;
constexpr const char* kBaselineLabel = "baseline";

/// The options `compare` shares with `run`, so both check and load them the same way.
RunOptions sceneAndClock(const CompareOptions& options) {
  RunOptions run;
  run.scenePath = options.scenePath;
  run.presetName = options.presetName;
  run.duration = options.duration;
  run.dt = options.dt;
  run.every = options.every;
  return run;
}

std::vector<RunSpec> parseSpecs(const std::vector<std::string>& texts) {
  if (texts.size() < kMinRuns || texts.size() > RunGroup::kMaxRuns) {
    throw UsageError("--run: compare takes " + std::to_string(kMinRuns) + " to " +
                     std::to_string(RunGroup::kMaxRuns) + " runs (got " +
                     std::to_string(texts.size()) + ")");
  }
  std::vector<RunSpec> specs;
  for (const std::string& text : texts)
    specs.push_back(parseRunSpec(text));  // throws std::invalid_argument naming the spec
  return specs;
}

double meanRadius(const Simulation& simulation) {
  double sum = 0.0;
  for (const double radius : simulation.radii())
    sum += radius;
  return simulation.ballCount() > 0 ? sum / static_cast<double>(simulation.ballCount()) : 0.0;
}

/// Σ m|v| (N·s): how much momentum is in motion, even when it sums to zero.
double speedMomentum(const Simulation& simulation) {
  double sum = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i)
    sum += simulation.masses()[i] * length(simulation.velocities()[i]);
  return sum;
}

/// Every stepper of the group in stepping order (the runs, then the baseline): its simulation,
/// its divergence from run 0, and what is recorded of it.
class Recorder {
 public:
  Recorder(const RunGroup& group, double departThreshold)
      : group_(group), departThreshold_(departThreshold) {
    const std::vector<std::string> labels = group.labels();
    for (std::size_t i = 0; i < stepperCount(); ++i) {
      ComparedRun run;
      run.label = i < labels.size() ? labels[i] : kBaselineLabel;
      run.start = simulation(i).metrics();
      run.startSpeedMomentum = speedMomentum(simulation(i));
      runs_.push_back(run);
      plots::CompareCurve curve;
      curve.label = run.label;
      curve.baseline = i >= labels.size();
      curves_.push_back(curve);
    }
    stepping_.resize(stepperCount());
  }

  std::size_t stepperCount() const { return group_.runCount() + (group_.hasBaseline() ? 1 : 0); }

  const Simulation& simulation(std::size_t i) const {
    return i < group_.runCount() ? group_.run(i) : *group_.baseline();
  }

  /// Stepper i's figure among the group's divergences `now`: a run's, or the baseline's.
  static const Divergence& divergence(const GroupDivergences& now, std::size_t i) {
    return i < now.fromRunZero.size() ? now.fromRunZero[i] : *now.baseline;
  }

  void addSteppingTime(std::size_t i, Clock::duration took) { stepping_[i] += took; }

  /// After every step: notes the first time each run's divergence exceeds the threshold. Only
  /// the runs not yet departed are measured (O(balls) each, every step).
  void checkDeparture() {
    for (std::size_t i = 1; i < stepperCount(); ++i) {
      if (runs_[i].departedAt) continue;
      const Divergence now =
          i < group_.runCount() ? group_.divergence(i) : *group_.baselineDivergence();
      if (now.rmsPositionDifference > departThreshold_) runs_[i].departedAt = group_.time();
    }
  }

  /// One row per stepper, all of one moment (GroupDivergences): the app's compare readout
  /// shows the same figures.
  void writeCsvRows(CompareCsv& csv) const {
    const GroupDivergences now = group_.divergences();
    for (std::size_t i = 0; i < stepperCount(); ++i)
      csv.writeRow(runs_[i].label, simulation(i).metrics(), divergence(now, i));
  }

  void addChartPoints() {
    const GroupDivergences now = group_.divergences();
    for (std::size_t i = 0; i < stepperCount(); ++i) {
      plots::CompareCurve& curve = curves_[i];
      curve.times.push_back(simulation(i).time());
      curve.rmsDivergence.push_back(divergence(now, i).rmsPositionDifference);
      const Metrics metrics = simulation(i).metrics();
      curve.energyResidual.push_back(metrics.energyResidual);
      curve.initialEnergy = metrics.initialEnergy;
    }
  }

  /// The runs as they ended.
  std::vector<ComparedRun> finish() {
    const GroupDivergences now = group_.divergences();
    for (std::size_t i = 0; i < stepperCount(); ++i) {
      runs_[i].end = simulation(i).metrics();
      runs_[i].rmsDivergence = divergence(now, i).rmsPositionDifference;
      runs_[i].steppingSeconds = std::chrono::duration<double>(stepping_[i]).count();
    }
    return runs_;
  }

  std::vector<plots::CompareCurve>& curves() { return curves_; }

 private:
  const RunGroup& group_;
  double departThreshold_;
  std::vector<ComparedRun> runs_;
  std::vector<Clock::duration> stepping_;
  std::vector<plots::CompareCurve> curves_;
};

}  // namespace

void compareCommand(const CompareOptions& options, std::ostream& out) {
  const RunOptions shared = sceneAndClock(options);
  checkRunNumbers(shared);
  const std::vector<RunSpec> specs = parseSpecs(options.runs);
  const Scene scene = loadRunScene(shared, std::cerr);
  if (options.csvPath) checkWritableFile(*options.csvPath, "--csv");
  if (options.chartPath) checkWritableFile(*options.chartPath, "--chart");

  RunGroup group(scene, specs, [](const RunSpec& spec) { return createBackend(spec); });
  if (options.dt) group.setDt(*options.dt);
  if (options.baseline) group.setBaseline(true);
  const std::uint64_t steps = stepCount(options.duration, group.dt());
  const auto every = static_cast<std::uint64_t>(options.every);
  const double departThreshold = 0.1 * meanRadius(group.run(0));

  std::optional<CompareCsv> csv;
  if (options.csvPath) csv.emplace(*options.csvPath);
  Recorder recorder(group, departThreshold);
  const std::uint64_t chartEvery = (steps + kMaxChartPoints - 1) / kMaxChartPoints;
  if (csv) recorder.writeCsvRows(*csv);
  if (options.chartPath) recorder.addChartPoints();

  // Each backend step is timed on its own, so every run's steps/s is its own cost although the
  // runs take turns on one thread.
  ProgressLine progress(!options.quiet && ProgressLine::stderrIsTerminal(), steps);
  std::vector<BackendStep> pending;
  pending.reserve(RunGroup::kMaxRuns + 1);
  for (std::uint64_t step = 1; step <= steps; ++step) {
    group.beginSteps(pending);
    for (std::size_t i = 0; i < pending.size(); ++i) {
      const Clock::time_point begin = Clock::now();
      pending[i].run();
      recorder.addSteppingTime(i, Clock::now() - begin);
    }
    // A run whose backend failed ends the comparison, with the backend's line (exit 1).
    if (const auto failures = group.finishSteps(pending); !failures.empty())
      throw std::runtime_error(failures.front().message);
    recorder.checkDeparture();
    const bool last = step == steps;
    if (csv && (step % every == 0 || last)) recorder.writeCsvRows(*csv);
    if (options.chartPath && (step % chartEvery == 0 || last)) recorder.addChartPoints();
    progress.update(step, group.time());
  }
  progress.clear();
  if (csv) csv->close();
  for (std::size_t i = 0; i < group.runCount(); ++i)
    printRunWarnings(group.run(i), group.spec(i).backend, group.spec(i).text(), std::cerr);

  CompareSummary summary;
  summary.sceneName = scene.name;
  summary.sceneSource = sceneSource(shared);
  summary.balls = group.ballCount();
  summary.steps = steps;
  summary.dt = group.dt();
  summary.departThreshold = departThreshold;
  summary.baselineDisplacement = RunGroup::kBaselineDisplacement;
  summary.runs = recorder.finish();
  summary.hasBaseline = group.hasBaseline();

  if (options.chartPath) {
    plots::CompareChart chart;
    chart.title = "Compare on '" + scene.name + "' (" + std::to_string(summary.balls) +
                  " balls, dt " + text::readableText(summary.dt, 4) + " s)";
    chart.duration = group.time();
    chart.departThreshold = departThreshold;
    chart.curves = std::move(recorder.curves());
    plots::saveCompareChart(chart, *options.chartPath);
  }
  if (!options.quiet) printCompareSummary(summary, out);
}

}  // namespace fooball::cli
