// Step cost of the Box2D backend against ball count in the standard gas, beside the same scene
// built straight on Box2D (RawBox2dWorld) at the same dt and substeps; and what the backend's
// state read-out costs next to its step. The first step is not timed.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "box2d/box2d_backend.h"
#include "fooball/standard_scenes.h"
#include "gas_counters.h"
#include "raw_box2d_world.h"

namespace fooball::benchmarks {
namespace {

constexpr double kDt = 1.0 / 60.0;  // s

Scene gasFor(const benchmark::State& state) {
  return standardGas(static_cast<std::size_t>(state.range(0)),
                     static_cast<double>(state.range(1)) / 100.0);
}

/// Args: balls, packing fraction in percent, substeps (Box2D steps per 1/60 s step).
void Box2dGasStep(benchmark::State& state) {
  const Scene scene = gasFor(state);
  auto backend = makeBox2dBackend();
  backend->setOption("substeps", static_cast<double>(state.range(2)));
  backend->load(scene);
  backend->step(kDt, {});
  const std::uint64_t collisionsBefore = backend->counters().ballCollisions;
  for (auto _ : state)
    backend->step(kDt, {});
  setStepCounters(state, scene.balls.size(), backend->counters().ballCollisions - collisionsBefore);
}

/// The same scene, dt and substeps straight on Box2D: the baseline of Box2dGasStep.
void RawBox2dGasStep(benchmark::State& state) {
  const Scene scene = gasFor(state);
  RawBox2dWorld world(scene);
  const int substeps = static_cast<int>(state.range(2));
  world.step(kDt, substeps);
  for (auto _ : state)
    world.step(kDt, substeps);
  setStepCounters(state, scene.balls.size());
}

/// Both run the same simulated second from the same state: the raw scene loses energy to
/// friction and rotation (half its kinetic energy in 2 s), and a colder gas is cheaper to step,
/// so letting each run as long as it likes would favour the one that gets the physics wrong.
constexpr int kTimedSteps = 60;

/// Registers Box2dGasStep and RawBox2dGasStep one configuration at a time, each backend run
/// right before the raw run of the same configuration: on a shared machine the load changes
/// within minutes, so a ratio is only fair between neighbouring measurements (registered as two
/// grids, every backend run came before every raw one).
[[maybe_unused]] const bool kGasStepsRegistered = [] {
  for (const std::int64_t balls : {1'000, 2'000, 5'000, 10'000, 20'000}) {
    for (const std::int64_t phiPercent : kPackingPercents) {
      for (const std::int64_t substeps : {1, 4}) {
        for (const auto& [name, run] : {std::pair{"Box2dGasStep", &Box2dGasStep},
                                        std::pair{"RawBox2dGasStep", &RawBox2dGasStep}}) {
          benchmark::RegisterBenchmark(name, run)
              ->ArgNames({"balls", "phi_percent", "substeps"})
              ->Args({balls, phiPercent, substeps})
              ->Iterations(kTimedSteps)
              ->Repetitions(3)
              ->Unit(benchmark::kMillisecond)
              ->UseRealTime()
              ->ComputeStatistics("min", minimum);
        }
      }
    }
  }
  return true;
}();

/// Args: balls. A step with the backend's default options, then readState into the caller's
/// arrays, timed apart: `readout_share` is the read-out's time over the step's (the Simulation
/// reads the state after every step).
void Box2dReadout(benchmark::State& state) {
  using Clock = std::chrono::steady_clock;
  const Scene scene = standardGas(static_cast<std::size_t>(state.range(0)), 0.2);
  auto backend = makeBox2dBackend();
  backend->load(scene);
  std::vector<Vec2> positions(scene.balls.size());
  std::vector<Vec2> velocities(scene.balls.size());
  backend->step(kDt, {});
  double stepSeconds = 0.0;
  double readSeconds = 0.0;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    backend->step(kDt, {});
    const Clock::time_point stepped = Clock::now();
    backend->readState(positions, velocities);
    benchmark::DoNotOptimize(positions.data());
    const Clock::time_point read = Clock::now();
    stepSeconds += std::chrono::duration<double>(stepped - start).count();
    readSeconds += std::chrono::duration<double>(read - stepped).count();
    state.SetIterationTime(std::chrono::duration<double>(read - start).count());
  }
  state.counters["readout_share"] = readSeconds / stepSeconds;
  state.counters["readout_ns_per_ball"] =
      1e9 * readSeconds / static_cast<double>(state.iterations() * scene.balls.size());
}

BENCHMARK(Box2dReadout)
    ->ArgName("balls")
    ->Arg(1'000)
    ->Arg(5'000)
    ->Arg(20'000)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->ComputeStatistics("min", minimum);

}  // namespace
}  // namespace fooball::benchmarks
