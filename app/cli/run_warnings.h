#pragma once

#include <ostream>
#include <string_view>

#include "fooball/simulation.h"

namespace fooball::cli {

/// The warnings a run earns by its end, one line each on `err`, with or without --quiet: steps
/// cut short (cutShortNotice) and the limits of its method it is beyond (methodLimitNotice, with
/// the boundaries `backendName` states in the registry; not for a run that took no step).
/// `runLabel` names the run in compare
/// ("run elastic: …"); empty for `run`, which has one.
void printRunWarnings(const Simulation& run, std::string_view backendName,
                      std::string_view runLabel, std::ostream& err);

}  // namespace fooball::cli
