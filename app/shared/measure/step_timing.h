#pragma once

#include <optional>
#include <stop_token>

#include "fooball/backend.h"

namespace fooball::measure {

/// s of CPU time used by this process so far, all threads together.
double processCpuSeconds();

/// The median wall-clock time (ms) of `timedSteps` steps of `dt` seconds each, timed one by
/// one after one untimed step: the first step grows buffers and sorts the balls, which says
/// nothing about the steady state (Box2D v3's benchmark habit). The median rather than the mean,
/// so a step that lost the CPU to another process does not count. Empty when `stop` is requested
/// (checked between steps).
std::optional<double> medianStepMs(Backend& backend, double dt, int timedSteps,
                                   std::stop_token stop = {});

}  // namespace fooball::measure
