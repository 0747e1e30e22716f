#pragma once

#include "ball_arrays.h"
#include "fooball/vec2.h"

namespace fooball::elastic {

/// Moves every ball for `h` seconds under gravity `g` (m/s²) and linear drag `c` (1/s),
/// integrated exactly (not Euler): with c = 0, x += v h + ½ g h²; with drag,
/// v(t) = v∞ + (v0 − v∞) e^{−ct} with v∞ = g/c, and x follows by integrating v.
/// Returns the mechanical energy (J) drag removed: −(ΔKE + ΔPE), exact for this flight.
double flyFreely(BallArrays& balls, double h, Vec2 g, double c);

}  // namespace fooball::elastic
