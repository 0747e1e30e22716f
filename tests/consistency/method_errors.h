#pragma once

#include <algorithm>
#include <cmath>

#include "fooball/backend.h"

namespace fooball::testing {

/// How far one backend's answer may lie from the exact one on a short simple scene, from the
/// method's known errors (not fitted to its output). Every bound below is a worst case. Each
/// backend's model is its row in tests/backend_profiles.cpp; methodError() below fills in the
/// solver step from the options it runs with.
struct MethodError {
  /// true: the method finds contacts only where its solver steps end, and steps dt over its
  /// substeps (the option of role OptionRole::Substeps; dt when it has none). false: event-driven,
  /// contacts at their exact times (solverStep stays 0).
  bool timeStepped = false;
  /// s, one solver step: a time-stepped method finds a contact only at the end of the solver
  /// step in which the balls start to overlap, up to this long after the true contact.
  double solverStep = 0.0;
  /// How many solver-step overlaps u·τ (u the closing speed, τ ≤ solverStep the lateness) the
  /// bodies' separation lags behind the exact one after a contact, along the contact normal.
  double contactLag = 0.0;
  /// The same for a bounce off a wall.
  double wallLag = 0.0;
  /// m, the deepest a wall contact may get before it is handled even when u·solverStep is
  /// smaller (continuous collision that stops short of a target depth).
  double contactDepthFloor = 0.0;
  /// The method integrates gravity and drag with semi-implicit Euler (v += h·g; x += h·v): the
  /// positions follow the exact parabola of a velocity h·g/2 off the reported one. false: it
  /// flies exactly (closed-form parabola and exponential).
  bool eulerFlight = false;
  /// m per solver step: rounding of a coordinate of box size. double: ½ ulp(16 m) ≈ 2e-15,
  /// negligible (held at 1e-9 m overall).
  double positionRoundingPerStep = 0.0;
  /// Relative velocity rounding per solver step.
  double velocityRoundingPerStep = 0.0;

  /// m, the deepest a contact with closing speed `u` (m/s) can be when it is found; the floor
  /// applies to walls only (no backend runs continuous collision between balls by default).
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

/// `model` (a backend's row in tests/backend_profiles.cpp) for `backend` stepped at `dt` seconds
/// with its current options.
inline MethodError methodError(MethodError model, const Backend& backend, double dt) {
  if (!model.timeStepped) return model;
  const OptionSpec* substeps = backend.options().withRole(OptionRole::Substeps);
  model.solverStep = substeps != nullptr ? dt / backend.options().value(substeps->name) : dt;
  return model;
}

}  // namespace fooball::testing
