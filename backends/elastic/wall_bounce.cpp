#include "wall_bounce.h"

#include <algorithm>
#include <cmath>

namespace fooball::elastic {

namespace {

/// One axis: walls at 0 (inward normal +1) and at `length` (inward normal −1).
struct AxisWalls {
  bool lowOn;
  bool highOn;
  double length;   ///< m
  double gravity;  ///< m/s², component along the axis
};

/// New normal speed for a ball mirrored 2δ inward along a normal n with g·n = `gravityInward`.
double outgoingSpeed(double incomingSpeed, double penetration, double gravityInward) {
  const double speedSquared = incomingSpeed * incomingSpeed + 4.0 * penetration * gravityInward;
  return speedSquared > 0.0 ? std::sqrt(speedSquared) : 0.0;
}

void bounceAxis(std::vector<double>& position, std::vector<double>& velocity,
                const BallArrays& balls, const AxisWalls& axis, BackendCounters& counters) {
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double r = balls.radius[i];
    double& p = position[i];
    double& v = velocity[i];
    // A ball already moving away got in by being pushed out of another ball, not by flying:
    // the clamps below put it back at contact.
    if (axis.lowOn && p < r && v < 0.0) {
      const double penetration = r - p;
      p += 2.0 * penetration;
      const double out = outgoingSpeed(v, penetration, axis.gravity);
      counters.wallImpulse += balls.mass[i] * (out - v);
      ++counters.wallCollisions;
      v = out;
    } else if (axis.highOn && p > axis.length - r && v > 0.0) {
      const double penetration = p - (axis.length - r);
      p -= 2.0 * penetration;
      const double out = -outgoingSpeed(v, penetration, -axis.gravity);
      counters.wallImpulse += balls.mass[i] * (v - out);
      ++counters.wallCollisions;
      v = out;
    }
    // A mirror deeper than the box is wide (a very fast ball) could land beyond the far wall.
    if (axis.lowOn) p = std::max(p, r);
    if (axis.highOn) p = std::min(p, axis.length - r);
  }
}

}  // namespace

void bounceOffWalls(BallArrays& balls, const Box& box, const Walls& walls, Vec2 gravity,
                    BackendCounters& counters) {
  if (walls.left || walls.right) {
    bounceAxis(balls.x, balls.vx, balls, {walls.left, walls.right, box.width, gravity.x}, counters);
  }
  if (walls.bottom || walls.top) {
    bounceAxis(balls.y, balls.vy, balls, {walls.bottom, walls.top, box.height, gravity.y},
               counters);
  }
}

}  // namespace fooball::elastic
