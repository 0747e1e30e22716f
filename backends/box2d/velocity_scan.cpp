#include "velocity_scan.h"

#include <algorithm>
#include <cmath>

namespace fooball::box2d_detail {

VelocityScan scanVelocities(std::span<b2Body* const> balls, std::span<const double> masses,
                            double capSpeed, MassSums sums, WallContainment* walls) {
  VelocityScan scan;
  double fastestSquared = 0.0;
  const double capSquared = capSpeed * capSpeed;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const b2Vec2 v =
        walls != nullptr ? walls->contain(*balls[i], masses[i]) : balls[i]->GetLinearVelocity();
    const Vec2 velocity{static_cast<double>(v.x), static_cast<double>(v.y)};
    const double speedSquared = lengthSquared(velocity);
    fastestSquared = std::max(fastestSquared, speedSquared);
    if (speedSquared >= capSquared) ++scan.ballsAtCap;
    if (sums == MassSums::kCompute) {
      scan.massSpeedSquared += masses[i] * speedSquared;
      scan.momentum += masses[i] * velocity;
    }
  }
  scan.fastestSpeed = std::sqrt(fastestSquared);
  return scan;
}

}  // namespace fooball::box2d_detail
