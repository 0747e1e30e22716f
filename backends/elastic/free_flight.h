#pragma once

#include <cmath>

#include "balls.h"
#include "fooball/vec2.h"

namespace fooball::elastic {

/// Moves a ball for `h` seconds under gravity `g` (m/s²) with no drag: exact for constant
/// acceleration, x += v h + ½ g h².
struct FlightWithoutDrag {
  FlightWithoutDrag(double h, Vec2 g) : h_(h), g_(g), halfH2_(0.5 * h * h) {}

  /// Returns the mechanical energy (J) drag removed: none.
  double fly(Ball& ball) const {
    ball.x += ball.vx * h_ + g_.x * halfH2_;
    ball.y += ball.vy * h_ + g_.y * halfH2_;
    ball.vx += g_.x * h_;
    ball.vy += g_.y * h_;
    return 0.0;
  }

 private:
  double h_;  ///< s
  Vec2 g_;    ///< m/s²
  double halfH2_;
};

/// Moves a ball for `h` seconds under gravity `g` (m/s²) and linear drag `c` (1/s), integrated
/// exactly (not Euler): v(t) = v∞ + (v0 − v∞) e^{−ct} with v∞ = g/c, and x follows by
/// integrating v.
struct FlightWithDrag {
  FlightWithDrag(double h, Vec2 g, double c)
      : h_(h),
        g_(g),
        decay_(std::exp(-c * h)),
        reach_(-std::expm1(-c * h) / c),  // s, ∫₀ʰ e^{−ct} dt; −expm1 stays accurate for ch ≪ 1
        terminal_(g / c) {}

  /// Returns the mechanical energy (J) drag removed from this ball: −(ΔKE + ΔPE), exact for
  /// this flight.
  double fly(Ball& ball) const {
    const double vx = ball.vx;
    const double vy = ball.vy;
    const double ux = vx - terminal_.x;
    const double uy = vy - terminal_.y;
    const double dx = terminal_.x * h_ + ux * reach_;
    const double dy = terminal_.y * h_ + uy * reach_;
    const double newVx = terminal_.x + ux * decay_;
    const double newVy = terminal_.y + uy * decay_;
    ball.x += dx;
    ball.y += dy;
    ball.vx = newVx;
    ball.vy = newVy;
    // −ΔKE − ΔPE with PE = −m g·p.
    return ball.mass *
           (0.5 * (vx * vx + vy * vy - newVx * newVx - newVy * newVy) + g_.x * dx + g_.y * dy);
  }

 private:
  double h_;  ///< s
  Vec2 g_;    ///< m/s²
  double decay_;
  double reach_;   ///< s
  Vec2 terminal_;  ///< m/s
};

}  // namespace fooball::elastic
