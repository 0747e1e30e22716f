#pragma once

#include <string>
#include <string_view>

#include "case_limits.h"
#include "random_case.h"
#include "registry.h"

namespace fooball::robustness {

/// The robustness tolerances of `backend` (its row in tests/backend_profiles.cpp). Fails the
/// test (throws) for a backend without a row.
Tolerances tolerancesFor(std::string_view backend);

/// The work cap of `backend` (its row in tests/backend_profiles.cpp).
WorkCap workCapFor(std::string_view backend);

/// Runs `c` on a new `backend` through the Simulation driver (at most until `cap` is passed)
/// and checks after every step: positions and velocities finite; ball count unchanged; in a
/// closed box, every centre inside the box (give or take the backend's wall slack). At the end
/// of an isolated case the total energy must not have grown by more than `tolerances`. Returns
/// the first violation, or "" when there is none.
std::string runCase(const RandomCase& c, const BackendInfo& backend, const Tolerances& tolerances,
                    const WorkCap& cap = {});

}  // namespace fooball::robustness
