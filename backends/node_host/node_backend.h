#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "fooball/backend.h"

namespace fooball {

/// An engine that runs in JavaScript or WebAssembly, behind the Node.js host (DESIGN.md,
/// "Engines in another runtime"): its adapter is backends/js/adapters/<name>.js.
struct JsEngine {
  std::string_view name;     ///< the registry name and the adapter's, e.g. "matter"
  std::string_view package;  ///< the node_modules folder it needs, e.g. "matter-js"
  std::vector<OptionSpec> (*optionSpecs)();
};

/// A Backend that starts one Node.js host for `engine` at its first load() and keeps it until it
/// is destroyed or the host fails. It can be created where Node.js is missing (so its options can
/// be listed); load() then throws std::runtime_error with the reason and the fix. A host that
/// crashes, exits, hangs or answers garbage makes the call throw node_host::HostError (a
/// std::runtime_error); the next load() starts a new host.
std::unique_ptr<Backend> makeNodeBackend(const JsEngine& engine);

}  // namespace fooball
