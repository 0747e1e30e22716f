#include "free_flight.h"

#include <cmath>

namespace fooball::elastic {

double flyFreely(BallArrays& balls, double h, Vec2 g, double c) {
  const std::size_t count = balls.size();
  double* x = balls.x.data();
  double* y = balls.y.data();
  double* vx = balls.vx.data();
  double* vy = balls.vy.data();
  if (c == 0.0) {
    const double halfH2 = 0.5 * h * h;
    for (std::size_t i = 0; i < count; ++i) {
      x[i] += vx[i] * h + g.x * halfH2;
      y[i] += vy[i] * h + g.y * halfH2;
      vx[i] += g.x * h;
      vy[i] += g.y * h;
    }
    return 0.0;
  }

  // Per step, one exponential for all balls. -expm1 keeps (1 − e^{−ch}) accurate when ch ≪ 1.
  const double decay = std::exp(-c * h);
  const double reach = -std::expm1(-c * h) / c;  // s, ∫₀ʰ e^{−ct} dt
  const Vec2 terminal = g / c;                   // m/s
  double dragLoss = 0.0;
  const double* mass = balls.mass.data();
  for (std::size_t i = 0; i < count; ++i) {
    const double ux = vx[i] - terminal.x;
    const double uy = vy[i] - terminal.y;
    const double dx = terminal.x * h + ux * reach;
    const double dy = terminal.y * h + uy * reach;
    const double newVx = terminal.x + ux * decay;
    const double newVy = terminal.y + uy * decay;
    // −ΔKE − ΔPE with PE = −m g·p.
    dragLoss += mass[i] * (0.5 * (vx[i] * vx[i] + vy[i] * vy[i] - newVx * newVx - newVy * newVy) +
                           g.x * dx + g.y * dy);
    x[i] += dx;
    y[i] += dy;
    vx[i] = newVx;
    vy[i] = newVy;
  }
  return dragLoss;
}

}  // namespace fooball::elastic
