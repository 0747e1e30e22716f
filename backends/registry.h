#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "fooball/backend.h"
#include "fooball/method_limits.h"
#include "fooball/run_spec.h"

namespace fooball {

/// One physics method the programs can run.
struct BackendInfo {
  std::string_view name;         ///< used by --backend and the GUI dropdown, e.g. "elastic"
  std::string_view description;  ///< one line
  std::unique_ptr<Backend> (*create)();
  /// Where the method was measured to stop being right (docs/accuracy.md): stated in the
  /// backend's own header, checked by crossedLimits (fooball/limit_check.h).
  MethodLimits limits;
};

/// Every backend, in the order users see them.
std::span<const BackendInfo> registeredBackends();

/// The backend called `name`; throws std::invalid_argument listing the known names.
const BackendInfo& backendInfo(std::string_view name);

/// Creates the backend called `name`; throws std::invalid_argument listing the known names.
std::unique_ptr<Backend> createBackend(std::string_view name);

/// Creates the backend `spec` names with its options set (a BackendFactory); throws
/// std::invalid_argument naming the spec and the reason.
std::unique_ptr<Backend> createBackend(const RunSpec& spec);

}  // namespace fooball
