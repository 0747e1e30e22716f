#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace fooball::robustness {

/// The cases one run of the random suite takes, from its environment.
struct CaseSelection {
  std::vector<std::uint64_t> seeds;
  /// One line to print when the run is not the suite's default (a single case): "" otherwise.
  std::string notice;
  /// Why the run must fail instead ("" when it may go on): a variable that is not a number, or
  /// FOOBALL_CASE_SEED set in CI, where it would silently shrink the suite to one case.
  std::string error;
};

/// The default cases are seeds 1…2'000, or 1…500 under the sanitizers (FOOBALL_SANITIZED=1: they
/// reach every line of engine/, backends/ and app/ that 1…1'000 reach, and all but 8 of 2'621
/// branch outcomes; the optimised build runs all 2'000 for the invariants themselves);
/// FOOBALL_SOAK=N runs 1…N instead; FOOBALL_CASE_SEED=S runs case S alone (to reproduce a
/// failure), with a notice, and is an error when CI is set (to anything but "", "0" or "false",
/// as CI services set CI=true). `environment` reads a variable as std::getenv does (nullptr when
/// unset).
CaseSelection selectCases(const std::function<const char*(const char*)>& environment);

}  // namespace fooball::robustness
