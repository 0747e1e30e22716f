#pragma once

#include <memory>
#include <string>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

/// matter.js 0.20.0 in the Node.js host, set up as its users set it up for restitution 1
/// (backends/js/adapters/matter.js says what it sets and why, and its scale of 64 px/m).
std::unique_ptr<Backend> makeMatterBackend();

/// Why matter.js cannot run here, with the fix; empty when it can.
std::string matterUnavailable();

/// Not measured on the failure map yet: no limit is stated, so the check warns of none.
inline constexpr MethodLimits kMatterLimits{};

}  // namespace fooball
