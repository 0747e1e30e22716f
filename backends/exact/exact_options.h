#pragma once

#include <vector>

#include "event_driven_world.h"
#include "fooball/options.h"

namespace fooball::exact {

/// The option specs the exact backend registers, with EventLimits' defaults.
std::vector<OptionSpec> exactOptionSpecs();

/// The backend's options as the world uses them (EventLimits): read once when an option changes.
/// `options` must hold the specs of exactOptionSpecs(); OptionSet has checked the ranges.
EventLimits readEventLimits(const OptionSet& options);

}  // namespace fooball::exact
