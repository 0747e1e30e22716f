#pragma once

#include <memory>
#include <span>
#include <string>
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
  /// Why it cannot run on this machine, with the fix, e.g. an engine in the Node.js host where
  /// Node.js or its npm package is missing; empty when it can. nullptr: it always can. An
  /// unavailable backend is still listed and created (its options are known); its load() throws
  /// std::runtime_error with the same reason.
  std::string (*unavailable)() = nullptr;
  /// Where the method does not run as native code, what it runs as, e.g. "JavaScript" or
  /// "WebAssembly" (in the Node.js host): said beside its speed, so nobody reads it as native.
  std::string_view runtime = {};
};

/// info.unavailable's answer, or empty for a backend that always runs.
std::string unavailableReason(const BackendInfo& info);

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
