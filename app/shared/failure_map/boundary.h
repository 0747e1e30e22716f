#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "failure_map.h"

namespace fooball::failure_map {

/// Where one curve (a sweep, a backend, a variant) starts to fail, walking its grid from the
/// easy end to the hard end.
struct Boundary {
  std::string backend;
  std::string variant;
  std::optional<double> lastPass;   ///< the last passing parameter before the first failure
  std::optional<double> firstFail;  ///< the first failing parameter; none: passes everywhere
  bool passesAgain = false;         ///< some harder point after the first failure passes
};

/// One boundary per curve of `points` (all of `spec`), in the order the curves first appear.
std::vector<Boundary> locateBoundaries(const SweepSpec& spec, std::span<const SweepPoint> points);

}  // namespace fooball::failure_map
