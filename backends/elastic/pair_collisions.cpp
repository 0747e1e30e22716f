#include "pair_collisions.h"

#include <cmath>

namespace fooball::elastic {

namespace {

void resolvePair(BallArrays& balls, std::uint32_t a, std::uint32_t b, BackendCounters& counters) {
  double dx = balls.x[b] - balls.x[a];
  double dy = balls.y[b] - balls.y[a];
  const double reach = balls.radius[a] + balls.radius[b];
  const double distanceSquared = dx * dx + dy * dy;
  if (distanceSquared >= reach * reach) return;

  double distance = std::sqrt(distanceSquared);
  if (distance == 0.0) {
    // Coincident centres: push apart along the relative velocity if there is one, else along x.
    dx = balls.vx[a] - balls.vx[b];
    dy = balls.vy[a] - balls.vy[b];
    distance = std::hypot(dx, dy);
    if (distance == 0.0) {
      dx = 1.0;
      dy = 0.0;
      distance = 1.0;
    }
  }
  const double nx = dx / distance;
  const double ny = dy / distance;
  const double ma = balls.mass[a];
  const double mb = balls.mass[b];
  // Shares of the correction: b moves ma/(ma+mb) of it, a the rest; written as 1/(1 + m/m')
  // so mass ratios of 1e8 neither overflow nor lose the light ball's share.
  const double shareA = 1.0 / (1.0 + ma / mb);
  const double shareB = 1.0 / (1.0 + mb / ma);
  const double penetration = reach - std::sqrt(distanceSquared);
  balls.x[a] -= nx * penetration * shareA;
  balls.y[a] -= ny * penetration * shareA;
  balls.x[b] += nx * penetration * shareB;
  balls.y[b] += ny * penetration * shareB;

  const double closingSpeed =
      (balls.vx[a] - balls.vx[b]) * nx + (balls.vy[a] - balls.vy[b]) * ny;  // m/s, > 0 approaching
  if (closingSpeed <= 0.0) return;
  // Δv_a = −2 mb/(ma+mb)·u_n, Δv_b = +2 ma/(ma+mb)·u_n: momentum and energy conserved exactly.
  const double kickA = 2.0 * shareA * closingSpeed;
  const double kickB = 2.0 * shareB * closingSpeed;
  balls.vx[a] -= nx * kickA;
  balls.vy[a] -= ny * kickA;
  balls.vx[b] += nx * kickB;
  balls.vy[b] += ny * kickB;
  ++counters.ballCollisions;
}

}  // namespace

void collidePairs(BallArrays& balls, const CellGrid& grid, BackendCounters& counters) {
  grid.forEachNearbyPair(
      [&](std::uint32_t a, std::uint32_t b) { resolvePair(balls, a, b, counters); });
}

}  // namespace fooball::elastic
