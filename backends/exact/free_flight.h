#pragma once

#include "fooball/vec2.h"

namespace fooball::exact {

/// Free flight under constant gravity g (m/s²) and linear drag c (1/s), dv/dt = g − c·v, solved
/// exactly. After τ seconds:
///   v(τ) = v0·decay + g·s,   p(τ) = p0 + v0·s + g·q,
/// with decay = e^{−cτ}, s = (1 − e^{−cτ})/c = ∫decay dτ and q = (τ − s)/c = ∫s dτ. Without drag
/// s = τ and q = τ²/2, the parabola. Two balls under the same gravity and drag share the g·q term,
/// so their relative motion is the straight line r0 + u·s: contact times stay a quadratic in s.
struct FlightFactors {
  double decay = 1.0;  ///< e^{−cτ}, dimensionless
  double s = 0.0;      ///< s (seconds), the re-parametrised time
  double q = 0.0;      ///< s² (seconds squared), ∫s dτ
};

/// The drag branch of flightFactors: needs exp and a series, kept out of line.
FlightFactors dragFlightFactors(double drag, double tau);

inline FlightFactors flightFactors(double drag, double tau) {
  if (drag == 0.0) return {1.0, tau, 0.5 * tau * tau};
  return dragFlightFactors(drag, tau);
}

inline Vec2 flightDisplacement(Vec2 velocity, Vec2 gravity, const FlightFactors& f) {
  return f.s * velocity + f.q * gravity;
}

inline Vec2 flightVelocity(Vec2 velocity, Vec2 gravity, const FlightFactors& f) {
  return f.decay * velocity + f.s * gravity;
}

/// The drag branch of timeForFlightParameter: τ = −ln(1 − c·s)/c.
double draggedFlightTime(double drag, double s);

/// The flight time τ (s) at which s(τ) reaches `s`; +∞ when drag stops the motion short of it
/// (s < 1/c for every finite τ).
inline double timeForFlightParameter(double drag, double s) {
  return drag == 0.0 ? s : draggedFlightTime(drag, s);
}

}  // namespace fooball::exact
