#include "wall_bounce.h"

#include <algorithm>
#include <cmath>

namespace fooball::elastic {

namespace {

/// New normal speed for a ball mirrored 2δ inward along a normal n with g·n = `gravityInward`.
double outgoingSpeed(double incomingSpeed, double penetration, double gravityInward) {
  const double speedSquared = incomingSpeed * incomingSpeed + 4.0 * penetration * gravityInward;
  return speedSquared > 0.0 ? std::sqrt(speedSquared) : 0.0;
}

}  // namespace

void WallBounce::bounceAxis(double& p, double& v, double r, double mass, const Axis& axis,
                            WallTally& tally) {
  // A ball already moving away got in by being pushed out of another ball, not by flying:
  // the clamps below put it back at contact.
  if (axis.lowOn && p < r && v < 0.0) {
    const double penetration = r - p;
    p += 2.0 * penetration;
    const double out = outgoingSpeed(v, penetration, axis.gravity);
    tally.impulse += mass * (out - v);
    ++tally.bounces;
    v = out;
  } else if (axis.highOn && p > axis.length - r && v > 0.0) {
    const double penetration = p - (axis.length - r);
    p -= 2.0 * penetration;
    const double out = -outgoingSpeed(v, penetration, -axis.gravity);
    tally.impulse += mass * (v - out);
    ++tally.bounces;
    v = out;
  }
  // A mirror deeper than the box is wide (a very fast ball) could land beyond the far wall.
  if (axis.lowOn) p = std::max(p, r);
  if (axis.highOn) p = std::min(p, axis.length - r);
}

}  // namespace fooball::elastic
