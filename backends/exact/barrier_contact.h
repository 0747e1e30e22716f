#pragma once

#include <cmath>
#include <limits>

namespace fooball::exact {

/// Without drag the gap is the parabola gap + rate·τ + ½·acceleration·τ² (see
/// firstBarrierContact). Roots are taken in the form that adds, never subtracts, quantities of
/// the same sign, so there is no cancellation.
inline double parabolicBarrierContact(double gap, double rate, double acceleration) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  if (gap <= 0.0) {
    if (rate < 0.0 || (rate == 0.0 && acceleration < 0.0)) return 0.0;
    if (acceleration >= 0.0) return kNever;
    const double discriminant = rate * rate - 2.0 * acceleration * gap;
    if (discriminant <= 0.0) return rate / -acceleration;  // turns back while still beyond
    return (rate + std::sqrt(discriminant)) / -acceleration;
  }
  if (acceleration == 0.0) return rate < 0.0 ? gap / -rate : kNever;
  const double discriminant = rate * rate - 2.0 * acceleration * gap;
  if (acceleration > 0.0) {
    if (rate >= 0.0 || discriminant < 0.0) return kNever;
    return 2.0 * gap / (-rate + std::sqrt(discriminant));
  }
  if (rate < 0.0) return 2.0 * gap / (-rate + std::sqrt(discriminant));
  return (rate + std::sqrt(discriminant)) / -acceleration;
}

/// With drag c > 0 (see firstBarrierContact): the stationary point of the gap is found in
/// closed form, the root by Newton steps kept inside a bracket.
double draggedBarrierContact(double gap, double rate, double acceleration, double drag);

/// The first time (s, ≥ 0) a ball reaches a straight barrier — a wall, or a face of its cell —
/// moving towards it; +∞ if it never does. The barrier is described along its normal by the
/// gap (m) between ball and barrier, positive on the allowed side, which in free flight is
///   gap(τ) = gap + rate·s(τ) + acceleration·q(τ)        (free_flight.h)
/// where rate (m/s) is the gap's rate of change now and acceleration (m/s²) the normal
/// component of gravity (negative when gravity pushes towards the barrier). Its curvature
/// gap'' = (acceleration − c·rate)·e^{−cτ} never changes sign, so the gap has at most one
/// maximum or minimum and the first approaching contact is found exactly: a closed-form quadratic
/// without drag, a bracketed Newton iteration to full precision with it.
///
/// A gap that rounding left at or below zero counts as contact now when the ball is approaching
/// (or at rest and pushed in), and as no contact while it moves away; in that case the contact
/// is where it turns back (at the apex if it is still beyond the barrier there). So a contact is
/// never scheduled in the past and never repeated at the same instant after a bounce.
inline double firstBarrierContact(double gap, double rate, double acceleration, double drag) {
  if (drag == 0.0) return parabolicBarrierContact(gap, rate, acceleration);
  return draggedBarrierContact(gap, rate, acceleration, drag);
}

}  // namespace fooball::exact
