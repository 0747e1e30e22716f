#pragma once

#include <limits>
#include <string_view>

namespace fooball::robustness {

/// What a backend may do beyond the exact contract in a random case; each backend's values and
/// their reasons are its row in tests/backend_profiles.cpp.
struct Tolerances {
  double energyRelative = 0.0;  ///< growth of an isolated case's energy, of the energy at start
  double energyAbsolute = 0.0;  ///< of Σ m·(|g|·r_max + v_max²), for rounding near zero energy
  double wallSlack = 0.0;       ///< m a centre may lie outside a closed box
  bool energyKeptUnderGravity = true;  ///< false: the energy is checked only without gravity
  /// false: under gravity, the energy is checked only with ball collisions off
  bool energyKeptUnderGravityWithCollisions = true;
};

/// The most work a backend may spend on one case. drawCase bounds a case's size, but some
/// backends' cost grows with what happens in the run (Box2D's energy blow-up under gravity, the
/// exact solver's event cascades in piles): such a case stops early, after the step in which
/// the backend's own count of its work passes `max`. The count is deterministic, so a seed still
/// reproduces the same run; each backend's cap and its cost are in tests/backend_profiles.cpp.
struct WorkCap {
  std::string_view counter;  ///< a cumulative Backend::diagnostics() entry; "" for no cap
  bool perBall = false;      ///< the counter is weighted by (ball count + 1)
  double max = std::numeric_limits<double>::infinity();
};

}  // namespace fooball::robustness
