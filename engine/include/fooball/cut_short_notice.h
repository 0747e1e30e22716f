#pragma once

#include <string>

#include "fooball/backend.h"

namespace fooball {

/// What the programs say when a run's backend ended steps early (BackendCounters::cutShortSteps),
/// one line; empty when it ended none. fooball-cli writes it to stderr as a warning, the app
/// shows it in the status bar.
std::string cutShortNotice(const BackendCounters& counters);

}  // namespace fooball
