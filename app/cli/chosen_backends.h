#pragma once

#include <string>
#include <vector>

#include "registry.h"

namespace fooball::cli {

/// The backends named by repeated --backend flags, in that order; every registered backend when
/// none is named. Throws std::invalid_argument listing the known names for an unknown one.
std::vector<BackendInfo> chosenBackends(const std::vector<std::string>& names);

}  // namespace fooball::cli
