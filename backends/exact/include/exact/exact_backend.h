#pragma once

#include <memory>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

std::unique_ptr<Backend> makeExactBackend();

/// Where the event-driven solver was measured to stop being right (docs/accuracy.md): nowhere
/// in the tunnelling, packing, mass-ratio and scale sweeps. Its one failure, a resting pile
/// under strong gravity, happens only in steps cut short at an event cap (without one such a
/// step never ends), which the cut-short notice reports (cutShortNotice); so no limit here.
inline constexpr MethodLimits kExactLimits{};

}  // namespace fooball
