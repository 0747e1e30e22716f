// What a step back costs in the app (RunGroup::stepBack): the history re-steps every run from
// the latest anchor before the moment (fooball/run_history.h says why), so the cost is bounded
// by the anchors' spacing however long the history. One run of the named backend at its
// defaults (the app's) on the standard gas (packing fraction 0.2), a history of the given
// seconds at 60 steps per second; each timed step back goes from the newest moment to the one
// before it.

#include <benchmark/benchmark.h>

#include <string_view>

#include "fooball/run_group.h"
#include "fooball/standard_scenes.h"
#include "registry.h"

namespace fooball::benchmarks {
namespace {

constexpr int kStepsPerSecond = 60;  // the app's dt = 1/60 s

/// Args: balls, seconds of history. `steps_per_anchor` is the most steps one step back re-steps.
void RewindStepBack(benchmark::State& state, std::string_view backend) {
  const auto balls = static_cast<std::size_t>(state.range(0));
  const auto seconds = static_cast<int>(state.range(1));
  RunGroup group(standardGas(balls, 0.2), {parseRunSpec(backend)},
                 [](const RunSpec& spec) { return createBackend(spec); });
  group.setHistoryBound(RunHistory::kDefaultBound);
  for (int step = 0; step < seconds * kStepsPerSecond; ++step)
    group.step();
  const std::size_t newest = group.history()->size() - 1;
  for (auto _ : state) {
    state.PauseTiming();
    group.rewindTo(newest);  // steps on from the moment before: cheap
    state.ResumeTiming();
    group.stepBack();
  }
  state.counters["steps_per_anchor"] = static_cast<double>(group.history()->stepsPerAnchor(balls));
}

BENCHMARK_CAPTURE(RewindStepBack, elastic, "elastic")
    ->ArgNames({"balls", "seconds"})
    ->ArgsProduct({{300, 10'000}, {10, 60}})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Box2D costs ~10× elastic per ball-step: its histories are kept short, or the setup takes
// minutes.
BENCHMARK_CAPTURE(RewindStepBack, box2d, "box2d")
    ->ArgNames({"balls", "seconds"})
    ->ArgsProduct({{300, 10'000}, {10}})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace fooball::benchmarks
