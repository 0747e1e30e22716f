#pragma once

#include <memory>
#include <string>

#include "fooball/backend.h"
#include "fooball/method_limits.h"

namespace fooball {

/// Rapier 2D in the Node.js host, 0.21.0 or 0.19.3 (option `version`), set up as its users set it
/// up for restitution 1 (backends/js/adapters/rapier.js says what it sets and why).
std::unique_ptr<Backend> makeRapierBackend();

/// Why Rapier cannot run here, with the fix; empty when it can.
std::string rapierUnavailable();

/// Not measured on the failure map yet: no limit is stated.
inline constexpr MethodLimits kRapierLimits{};

}  // namespace fooball
