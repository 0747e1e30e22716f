#pragma once

#include <ostream>

#include "compare_options.h"

namespace fooball::cli {

/// `fooball-cli compare`: steps 2 to 8 runs of one scene as a RunGroup (run 0 is the first
/// --run), optionally with the chaos baseline; writes CSV rows and a chart as asked and prints a
/// table of each run's speed, conservation and divergence from run 0 on `out` unless quiet.
/// Bad input (run count, specs, numbers, scene, paths) throws UsageError, SceneError or
/// std::invalid_argument (exit code 2); anything else is a failure of the runs (exit code 1).
void compareCommand(const CompareOptions& options, std::ostream& out);

}  // namespace fooball::cli
