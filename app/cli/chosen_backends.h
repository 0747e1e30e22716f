#pragma once

#include <string>
#include <vector>

#include "fooball/run_spec.h"
#include "registry.h"

namespace fooball::cli {

/// The backends named by repeated --backend flags, in that order; every registered backend when
/// none is named. Throws std::invalid_argument listing the known names for an unknown one.
std::vector<BackendInfo> chosenBackends(const std::vector<std::string>& names);

/// The runs named by repeated --backend flags, each a run spec (NAME[:KEY=VALUE,...]), in that
/// order; every registered backend at its defaults when none is named. Throws
/// std::invalid_argument naming a spec that is malformed or names an unknown backend or option.
std::vector<RunSpec> chosenRuns(const std::vector<std::string>& specs);

}  // namespace fooball::cli
