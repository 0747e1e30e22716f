#include "step_timing.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace fooball::measure {

namespace {

/// The median of `values` (the upper one of an even count); reorders them.
double median(std::vector<double>& values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// ms one step of `dt` takes, by the wall clock.
double timeStepMs(Backend& backend, double dt) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  backend.step(dt, {});
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

double processCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

std::optional<double> medianStepMs(Backend& backend, const StepTiming& timing,
                                   std::stop_token stop) {
  constexpr std::size_t kStepsBeforeGivingUp = 5;  // one slow step may be another process's
  std::vector<double> stepMs;
  for (int step = 0; step < timing.warmUpSteps; ++step) {
    if (stop.stop_requested()) return std::nullopt;
    const double ms = timeStepMs(backend, timing.dt);
    if (step == 0) continue;  // it grows buffers
    stepMs.push_back(ms);
    if (stepMs.size() < kStepsBeforeGivingUp) continue;
    std::vector<double> sofar = stepMs;
    if (const double typical = median(sofar); typical > timing.giveUpAboveMs) return typical;
  }
  stepMs.clear();
  for (int step = 0; step < timing.timedSteps; ++step) {
    if (stop.stop_requested()) return std::nullopt;
    stepMs.push_back(timeStepMs(backend, timing.dt));
  }
  return median(stepMs);
}

}  // namespace fooball::measure
