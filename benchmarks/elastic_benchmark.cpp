// Step cost of the elastic backend against ball count in the standard gas, one substep per
// 1/60 s step: ns per ball-step must stay flat (linear cost), the memory per ball small, and a
// second worker thread must nearly halve the step. The first step is not timed.

#include <benchmark/benchmark.h>

#include "elastic/elastic_backend.h"
#include "fooball/standard_scenes.h"
#include "gas_counters.h"

namespace fooball::benchmarks {
namespace {

constexpr double kDt = 1.0 / 60.0;  // s

/// Args: balls, packing fraction in percent. Counters beside the step cost:
/// `bytes_per_ball`, every buffer the backend holds (its "memory_bytes" reading, from the
/// vectors' capacities), and `heap_bytes_per_ball`, what the heap grew by from before the
/// backend was made to after its first steps (glibc's mallinfo2) — the two should agree.
void ElasticGasStep(benchmark::State& state) {
  const auto balls = static_cast<std::size_t>(state.range(0));
  const Scene scene = standardGas(balls, static_cast<double>(state.range(1)) / 100.0);
  const std::size_t heapBefore = heapBytes();
  auto backend = makeElasticBackend();
  backend->setOption("substeps", 1);
  backend->load(scene);
  backend->step(kDt, {});  // grows the buffers and sorts the balls by cell: not timed
  const double heapGrowth = static_cast<double>(heapBytes() - heapBefore);
  const std::uint64_t collisionsBefore = backend->counters().ballCollisions;
  for (auto _ : state)
    backend->step(kDt, {});
  setStepCounters(state, balls, backend->counters().ballCollisions - collisionsBefore);
  state.counters["bytes_per_ball"] =
      diagnostic(*backend, "memory_bytes") / static_cast<double>(balls);
  state.counters["heap_bytes_per_ball"] = heapGrowth / static_cast<double>(balls);
}

BENCHMARK(ElasticGasStep)
    ->ArgNames({"balls", "phi_percent"})
    ->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000},
                   {std::begin(kPackingPercents), std::end(kPackingPercents)}})
    ->Repetitions(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", minimum);

/// Args: balls, threads, balls_per_thread; the standard gas at packing fraction 0.2. Compare
/// the times at the same count: threads 1 against threads 2 with balls_per_thread 0 (two
/// workers always) for what a second worker saves or costs, and with the default 250'000 for
/// what the backend picks (the results are the same bit for bit:
/// tests/elastic_threads_test.cpp). Run it beside busy processes too: a worker that waits for
/// a descheduled one is where threads cost most. 64 steps each: four periods of the (serial)
/// reordering of the balls by cell, which a shorter run would catch or miss by chance.
void ElasticThreads(benchmark::State& state) {
  const auto balls = static_cast<std::size_t>(state.range(0));
  auto backend = makeElasticBackend();
  backend->setOption("substeps", 1);
  backend->setOption("threads", static_cast<double>(state.range(1)));
  backend->setOption("balls_per_thread", static_cast<double>(state.range(2)));
  backend->load(standardGas(balls, 0.2));
  backend->step(kDt, {});
  for (auto _ : state)
    backend->step(kDt, {});
  setStepCounters(state, balls);
  state.counters["workers"] = diagnostic(*backend, "workers");
}

BENCHMARK(ElasticThreads)
    ->ArgNames({"balls", "threads", "balls_per_thread"})
    ->ArgsProduct({{38, 300, 3'000, 30'000, 300'000, 600'000, 1'000'000}, {1, 2}, {0, 250'000}})
    ->Iterations(64)
    ->Repetitions(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", minimum);

}  // namespace
}  // namespace fooball::benchmarks
