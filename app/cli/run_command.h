#pragma once

#include <ostream>

#include "run_options.h"

namespace fooball::cli {

/// `fooball-cli run`: checks the options, loads the scene, runs it for the requested time
/// (writing metrics rows and a progress line as asked), saves the final state if asked and
/// prints the summary on `out` unless quiet.
/// Bad input throws UsageError, SceneError or std::invalid_argument (exit code 2); any other
/// exception is a failure of the run itself (exit code 1).
void runCommand(const RunOptions& options, std::ostream& out);

}  // namespace fooball::cli
