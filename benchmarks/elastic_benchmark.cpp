// Step cost of the elastic backend against ball count in the standard gas (packing fraction
// 0.2, one substep per 1/60 s step). Cost must grow linearly: ns per ball-step stays flat.

#include <benchmark/benchmark.h>

#include "elastic/elastic_backend.h"
#include "fooball/standard_scenes.h"

namespace fooball {
namespace {

void ElasticGasStep(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  auto backend = makeElasticBackend();
  backend->setOption("substeps", 1);
  backend->load(standardGas(count, 0.2));
  backend->step(1.0 / 60.0, {});  // the first step grows buffers and sorts: not timed
  for (auto _ : state)
    backend->step(1.0 / 60.0, {});
  state.counters["ball_steps"] = benchmark::Counter(
      static_cast<double>(count) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);  // s per ball-step
  state.counters["collisions_per_s"] = benchmark::Counter(
      static_cast<double>(backend->counters().ballCollisions), benchmark::Counter::kIsRate);
}

BENCHMARK(ElasticGasStep)
    ->RangeMultiplier(10)
    ->Range(1'000, 1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace fooball
