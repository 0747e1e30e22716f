#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fooball/backend.h"

namespace fooball::testing {

/// How far one backend's answer may lie from the exact one on a short simple scene, from the
/// method's known errors (not fitted to its output). Every bound below is a worst case.
struct MethodError {
  /// s, one solver step: a time-stepped method finds a contact only at the end of the solver
  /// step in which the balls start to overlap, up to this long after the true contact.
  double solverStep = 0.0;
  /// How many solver-step overlaps u·τ (u the closing speed, τ ≤ solverStep the lateness) the
  /// bodies' separation lags behind the exact one after a contact, along the contact normal.
  /// elastic: it moves the overlapping balls back to touching and reverses u there, so they
  /// are u·τ short of the exact separation u·τ (factor 1). Box2D: its velocity solver reverses
  /// u while the overlap u·τ remains, and the next position update only flies it out, so the
  /// overlap is never undone and the separation is 2u·τ short (factor 2). Its iterative
  /// velocity solver adds nothing here: one contact alone is solved exactly by the first
  /// iteration, and the position solver leaves alone an overlap that the step has flown out.
  double contactLag = 0.0;
  /// The same for a bounce off a wall. elastic reflects the ball at the exact time it crossed
  /// the wall, under gravity too (factor 0); Box2D reverses u at the overlap (factor 2).
  double wallLag = 0.0;
  /// m, the deepest a contact may get before it is handled even when u·solverStep is smaller:
  /// Box2D's continuous collision against the walls (static bodies) stops a ball at a target
  /// depth of 3 linear slops (3 × 5 mm) with a tolerance of a quarter slop (b2_time_of_impact).
  double contactDepthFloor = 0.0;
  /// Box2D integrates gravity and drag with semi-implicit Euler (v += h·g; x += h·v): the
  /// positions follow the exact parabola of a velocity h·g/2 off the reported one. The other
  /// backends fly exactly (closed-form parabola and exponential).
  bool eulerFlight = false;
  /// m per solver step: rounding of a coordinate of box size. double: ½ ulp(16 m) ≈ 2e-15,
  /// negligible (held at 1e-9 m overall). Box2D stores float: ½ ulp(8 … 16 m) = 2^−21 m.
  double positionRoundingPerStep = 0.0;
  /// Relative velocity rounding per solver step: float ε = 2^−23 for Box2D.
  double velocityRoundingPerStep = 0.0;

  /// m, the deepest a contact with closing speed `u` (m/s) can be when it is found; the floor
  /// applies to walls only (Box2D runs no continuous collision between balls by default).
  double contactDepth(double u, bool wall) const {
    return std::max(u * solverStep, wall ? contactDepthFloor : 0.0);
  }

  /// m and m/s: rounding after `seconds` of a run whose balls move no faster than `speed`.
  /// The 1e-9 floor covers double rounding over the short runs here (~1e-13 per operation).
  double positionRounding(double seconds, double speed) const {
    const double steps = solverSteps(seconds);
    return 1e-9 + steps * positionRoundingPerStep +
           steps * velocityRoundingPerStep * speed * seconds;
  }
  double velocityRounding(double seconds, double speed) const {
    return 1e-9 + solverSteps(seconds) * velocityRoundingPerStep * speed;
  }

 private:
  double solverSteps(double seconds) const {
    return solverStep > 0.0 ? std::ceil(seconds / solverStep) : 0.0;
  }
};

/// The error model of `backend` (freshly created, default options) stepped at `dt` seconds.
/// A backend without a model is an error: its tolerances must be stated before it is compared.
inline MethodError methodError(std::string_view name, const Backend& backend, double dt) {
  if (name == "exact") return {};  // event-driven: exact collision times, exact flight
  const double substeps = backend.options().value("substeps");
  if (name == "elastic") return {dt / substeps, 1.0, 0.0, 0.0, false, 0.0, 0.0};
  if (name == "box2d") {
    constexpr double kLinearSlop = 0.005;  // m, b2_linearSlop
    return {dt / substeps,
            2.0,
            2.0,
            3.25 * kLinearSlop,
            true,
            std::ldexp(1.0, -21),
            std::numeric_limits<float>::epsilon()};
  }
  throw std::invalid_argument("no error model for backend '" + std::string(name) +
                              "': state it in tests/consistency/method_errors.h");
}

}  // namespace fooball::testing
