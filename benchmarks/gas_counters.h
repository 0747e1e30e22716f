#pragma once

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fooball/backend.h"

namespace fooball::benchmarks {

/// The packing fractions every step-cost benchmark runs at, in percent: a dilute gas, the
/// standard gas of the capacity tool, and a dense one.
inline constexpr std::int64_t kPackingPercents[] = {5, 20, 40};

/// Sets the counters the step-cost suites share, after the timed loop: `ns_per_ball_step`
/// (wall-clock ns per ball per step, the number that stays flat when the cost is linear) and,
/// if given, `collisions_per_s` (ball–ball impulses in the timed steps per second).
inline void setStepCounters(benchmark::State& state, std::size_t balls,
                            std::uint64_t collisions = 0) {
  // Counted in units of 1e-9 ball-steps, a rate inverted is ns per ball-step.
  state.counters["ns_per_ball_step"] = benchmark::Counter(
      1e-9 * static_cast<double>(balls) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  if (collisions > 0) {
    state.counters["collisions_per_s"] =
        benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
  }
}

/// Bytes the heap holds now: small blocks plus mmapped ones (glibc).
inline std::size_t heapBytes() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

/// A backend's reading called `name`, 0 when it has none.
inline double diagnostic(const Backend& backend, std::string_view name) {
  for (const Diagnostic& reading : backend.diagnostics()) {
    if (reading.name == name) return reading.value;
  }
  return 0.0;
}

/// Keeps the smallest of the repetitions too (--benchmark_repetitions): the run least disturbed
/// by the rest of the machine, Box2D v3's benchmark habit.
inline double minimum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
}

}  // namespace fooball::benchmarks
