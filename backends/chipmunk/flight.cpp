#include "flight.h"

#include <cmath>

namespace fooball::chipmunk_detail {

double kickVelocities(std::span<cpBody* const> balls, std::span<const double> masses, Vec2 gravity,
                      double airResistance, double step) {
  const cpVect kick = cpv(gravity.x * step, gravity.y * step);  // m/s
  if (airResistance == 0.0) {
    for (cpBody* ball : balls)
      cpBodySetVelocity(ball, cpvadd(cpBodyGetVelocity(ball), kick));
    return 0.0;
  }
  const double factor = std::exp(-airResistance * step);
  const double takenFraction = 1.0 - factor * factor;  // of ½m|v|², what the drag takes
  double loss = 0.0;                                   // J
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const cpVect v = cpvadd(cpBodyGetVelocity(balls[i]), kick);
    loss += 0.5 * masses[i] * cpvlengthsq(v) * takenFraction;
    cpBodySetVelocity(balls[i], cpvmult(v, factor));
  }
  return loss;
}

}  // namespace fooball::chipmunk_detail
