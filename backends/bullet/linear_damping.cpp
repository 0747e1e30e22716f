#include "linear_damping.h"

#include <LinearMath/btScalar.h>

#include <cmath>

namespace fooball::bullet_detail {

float bulletLinearDamping(double airResistance) {
  return static_cast<float>(-std::expm1(-airResistance));
}

double bulletDampingFactor(float linearDamping, float bulletStep) {
  return static_cast<double>(btPow(btScalar(1) - linearDamping, bulletStep));
}

}  // namespace fooball::bullet_detail
