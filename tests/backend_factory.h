#pragma once

#include <memory>

#include "fooball/run_spec.h"
#include "registry.h"

namespace fooball::testing {

/// The registry's createBackend(const RunSpec&) as a RunGroup's backend factory (the name alone
/// is overloaded).
inline std::unique_ptr<Backend> makeBackend(const RunSpec& spec) {
  return createBackend(spec);
}

}  // namespace fooball::testing
