#include "step_timing.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace fooball::measure {

double processCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

std::optional<double> medianStepMs(Backend& backend, double dt, int timedSteps,
                                   std::stop_token stop) {
  using Clock = std::chrono::steady_clock;
  backend.step(dt, {});
  std::vector<double> stepMs;
  stepMs.reserve(static_cast<std::size_t>(timedSteps));
  for (int step = 0; step < timedSteps; ++step) {
    if (stop.stop_requested()) return std::nullopt;
    const Clock::time_point start = Clock::now();
    backend.step(dt, {});
    stepMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  const auto middle = stepMs.begin() + static_cast<std::ptrdiff_t>(stepMs.size() / 2);
  std::nth_element(stepMs.begin(), middle, stepMs.end());
  return *middle;
}

}  // namespace fooball::measure
