#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "fooball/backend.h"

namespace fooball {

/// One physics method the programs can run.
struct BackendInfo {
  std::string_view name;         ///< used by --backend and the GUI dropdown, e.g. "elastic"
  std::string_view description;  ///< one line
  std::unique_ptr<Backend> (*create)();
};

/// Every backend, in the order users see them.
std::span<const BackendInfo> registeredBackends();

/// Creates the backend called `name`; throws std::invalid_argument listing the known names.
std::unique_ptr<Backend> createBackend(std::string_view name);

}  // namespace fooball
