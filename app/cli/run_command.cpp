#include "run_command.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>

#include "fooball/scene_file.h"
#include "fooball/simulation.h"
#include "metrics_csv.h"
#include "progress_line.h"
#include "run_setup.h"
#include "run_summary.h"
#include "run_warnings.h"

namespace fooball::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// How many steps run between two clock reads. A clock read costs about as much as stepping a
/// few balls, so tiny scenes are timed in batches: the batch doubles while it takes under
/// 10 ms and halves above 50 ms, which also keeps the progress line live on heavy scenes.
class StepBatch {
 public:
  std::uint64_t size() const { return size_; }

  void adapt(std::uint64_t stepsRun, Clock::duration took) {
    if (stepsRun != size_) return;  // cut short by a metrics row: says nothing about speed
    if (took < std::chrono::milliseconds(10) && size_ < kMaxSize) size_ *= 2;
    if (took > std::chrono::milliseconds(50) && size_ > 1) size_ /= 2;
  }

 private:
  static constexpr std::uint64_t kMaxSize = 1 << 20;
  std::uint64_t size_ = 1;
};

struct LoopTiming {
  double wallSeconds = 0.0;     ///< the whole loop
  double physicsSeconds = 0.0;  ///< inside Simulation::step only
};

/// Runs `steps` steps, writing a metrics row after every `every`-th step and after the last.
LoopTiming runSteps(Simulation& simulation, std::uint64_t steps, std::uint64_t every,
                    MetricsCsv* csv, ProgressLine& progress) {
  const Clock::time_point loopStart = Clock::now();
  Clock::duration physicsTime{};
  StepBatch batch;
  std::uint64_t done = 0;
  std::uint64_t nextRow = csv != nullptr ? std::min(every, steps) : steps;
  while (done < steps) {
    const std::uint64_t count = std::min(batch.size(), nextRow - done);
    const Clock::time_point batchStart = Clock::now();
    for (std::uint64_t i = 0; i < count; ++i)
      simulation.step();
    const Clock::duration took = Clock::now() - batchStart;
    physicsTime += took;
    done += count;
    batch.adapt(count, took);
    if (csv != nullptr && done == nextRow) {
      csv->writeRow(simulation.metrics());
      nextRow = std::min(nextRow + every, steps);
    }
    progress.update(done, simulation.time());
  }
  return {std::chrono::duration<double>(Clock::now() - loopStart).count(),
          std::chrono::duration<double>(physicsTime).count()};
}

/// Σ m|v| (N·s): how much momentum is in motion, even when it sums to zero.
double speedMomentum(const Simulation& simulation) {
  double sum = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
    sum += simulation.masses()[i] * length(simulation.velocities()[i]);
  }
  return sum;
}

}  // namespace

void runCommand(const RunOptions& options, std::ostream& out) {
  // --duration 0 steps nothing: the scene is read and checked, the backend takes it, and --save
  // writes it back as it was read (saved_from and all, bit for bit), not as the backend holds it
  // (Box2D's state is float).
  const bool stepsNothing = options.duration == 0.0;
  checkRunNumbers(options, true);
  const std::string backendName = backendSpec(options).backend;
  std::unique_ptr<Backend> backend = configuredBackend(options);
  const Scene scene = loadRunScene(options, std::cerr);

  Simulation simulation(scene, std::move(backend));
  if (options.dt) simulation.setDt(*options.dt);
  const std::uint64_t steps = stepsNothing ? 0 : stepCount(options.duration, simulation.dt());

  if (options.savePath) checkWritableFile(*options.savePath, "--save");
  std::optional<MetricsCsv> csv;
  if (options.metricsPath) csv.emplace(*options.metricsPath);

  RunSummary summary;
  summary.sceneName = scene.name;
  summary.sceneSource = sceneSource(options);
  summary.backendName = backendName;
  summary.changedOptions = changedOptions(simulation.backend());
  summary.balls = simulation.ballCount();
  summary.steps = steps;
  summary.dt = simulation.dt();
  summary.start = simulation.metrics();
  summary.startSpeedMomentum = speedMomentum(simulation);
  if (csv) csv->writeRow(summary.start);

  ProgressLine progress(!options.quiet && ProgressLine::stderrIsTerminal(), steps);
  const LoopTiming timing = runSteps(simulation, steps, static_cast<std::uint64_t>(options.every),
                                     csv ? &*csv : nullptr, progress);
  progress.clear();

  if (csv) csv->close();
  if (options.savePath) {
    saveSceneFile(stepsNothing ? scene : simulation.savedScene(backendName), *options.savePath);
  }
  printRunWarnings(simulation, backendName, {}, std::cerr);
  if (options.quiet) return;

  summary.wallSeconds = timing.wallSeconds;
  summary.physicsSeconds = timing.physicsSeconds;
  summary.end = simulation.metrics();
  summary.diagnostics = simulation.backend().diagnostics();
  printRunSummary(summary, out);
}

}  // namespace fooball::cli
