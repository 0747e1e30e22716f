// Collisions per second of the event-driven `exact` backend on one core: a hard-disk gas of N
// equal balls at packing fraction φ, no gravity, no drag. Target: ≥ 1e6 collisions/s at
// N = 1e4, φ = 0.3. Swept over N ∈ {1e4, 1e5} and φ from a dilute gas (0.05) to a dense fluid
// (0.5).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "exact/exact_backend.h"
#include "fooball/scene.h"

namespace fooball {
namespace {

constexpr double kRadius = 0.5;  // m
constexpr double kSpeed = 1.0;   // m/s

/// N balls on a square lattice in a square box sized for packing fraction φ, each jittered
/// within its lattice cell (so none overlap), moving at kSpeed in a random direction.
Scene latticeGas(int count, double packingFraction) {
  const double side = std::sqrt(count * std::numbers::pi * kRadius * kRadius / packingFraction);
  const int perRow = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const double spacing = side / perRow;
  const double jitter = 0.5 * (spacing - 2.0 * kRadius);
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Scene scene;
  scene.name = "lattice gas";
  scene.box = {side, side};
  for (int i = 0; i < count; ++i) {
    const Vec2 centre{(i % perRow + 0.5) * spacing, (i / perRow + 0.5) * spacing};
    const Vec2 offset{(2.0 * unit(random) - 1.0) * jitter, (2.0 * unit(random) - 1.0) * jitter};
    const double angle = 2.0 * std::numbers::pi * unit(random);
    scene.balls.push_back({centre + offset, kSpeed * Vec2{std::cos(angle), std::sin(angle)},
                           kRadius, diskMass(kRadius), 0xffffff});
  }
  return scene;
}

double eventCount(const Backend& backend) {
  for (const Diagnostic& reading : backend.diagnostics()) {
    if (reading.name == "events") return reading.value;
  }
  return 0.0;
}

void BM_ExactCollisions(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const double packingFraction = static_cast<double>(state.range(1)) / 100.0;
  auto backend = makeExactBackend();
  backend->load(latticeGas(count, packingFraction));
  // Untimed first step: builds cells and calendar and measures the collision rate, from which
  // the timed step length is chosen to hold about one collision per ball.
  const double warmUp = 2.0;  // s
  backend->step(warmUp, {});
  const auto warmUpCollisions = static_cast<double>(backend->counters().ballCollisions);
  const double dt = warmUp * count / warmUpCollisions;
  const std::uint64_t before = backend->counters().ballCollisions;
  const double eventsBefore = eventCount(*backend);
  for (auto _ : state)
    backend->step(dt, {});
  const auto collisions = static_cast<double>(backend->counters().ballCollisions - before);
  state.counters["events_per_collision"] = (eventCount(*backend) - eventsBefore) / collisions;
  state.counters["collisions_per_s"] = benchmark::Counter(collisions, benchmark::Counter::kIsRate);
  state.counters["collisions_per_step"] = collisions / static_cast<double>(state.iterations());
  // ns per ball-step: the counter's value is ball-steps × 1e-9, inverted against the time.
  const double ballSteps = static_cast<double>(state.iterations()) * count;
  state.counters["ns_per_ball_step"] = benchmark::Counter(
      ballSteps * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_ExactCollisions)
    ->ArgNames({"balls", "phi_percent"})
    ->ArgsProduct({{10'000, 100'000}, {5, 10, 20, 30, 40, 50}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fooball
