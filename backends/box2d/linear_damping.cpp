#include "linear_damping.h"

#include <cmath>

namespace fooball::box2d_detail {

float box2dLinearDamping(double airResistance, float box2dStep) {
  const double step = static_cast<double>(box2dStep);
  return static_cast<float>(std::expm1(airResistance * step) / step);
}

float box2dDampingFactor(float linearDamping, float box2dStep) {
  return 1.0f / (1.0f + box2dStep * linearDamping);
}

double dampingLoss(const VelocityScan& before, double totalMass, Vec2 gravity, double box2dStep,
                   double dampingFactor) {
  const double massSpeedSquaredAfterGravity =
      before.massSpeedSquared + 2.0 * box2dStep * dot(gravity, before.momentum) +
      box2dStep * box2dStep * lengthSquared(gravity) * totalMass;
  return 0.5 * massSpeedSquaredAfterGravity * (1.0 - dampingFactor * dampingFactor);
}

}  // namespace fooball::box2d_detail
