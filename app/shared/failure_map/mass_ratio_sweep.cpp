// Mass ratio: one head-on hit of masses M and m (equal radii), checked against the closed form
// v1' = (M − m)/(M + m)·v1, v2' = 2M/(M + m)·v1 for a ball of mass M at v1 hitting m at rest.
// A solver that adds the two shares of an impulse in a lossy order, or iterates towards it in
// float, loses the light ball's share first.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "fooball/scene.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

constexpr double kPairRadius = 0.25;   // m
constexpr double kShooterSpeed = 1.0;  // m/s, of the shooter

/// Ball 0 (mass `shooterMass`, kg) at kShooterSpeed towards ball 1 (`targetMass`) at rest; the
/// largest error of the two outgoing velocities over kShooterSpeed, as the point at `ratio` of
/// `variant`.
SweepPoint headOn(std::string_view backend, std::string variant, double ratio, double shooterMass,
                  double targetMass) {
  Scene scene;
  scene.name = "mass ratio";
  scene.box = {8.0, 2.0};
  scene.balls = {{{2.0, 1.0}, {kShooterSpeed, 0.0}, kPairRadius, shooterMass},
                 {{2.0 + 2.0 * kPairRadius + 0.3, 1.0}, {}, kPairRadius, targetMass}};
  // 0.3 m to the hit, then ≤ 2 m/s for the rest of 1 s: both stay clear of the walls.
  const RunRecord run = runScene(scene, backend, 1.0);
  const double total = shooterMass + targetMass;
  const Vec2 shooterExact{(shooterMass - targetMass) / total * kShooterSpeed, 0.0};
  const Vec2 targetExact{2.0 * shooterMass / total * kShooterSpeed, 0.0};
  const double error =
      std::max(length(run.velocities[0] - shooterExact), length(run.velocities[1] - targetExact)) /
      kShooterSpeed;
  return measuredPoint(scene, std::move(variant), ratio, error);
}

}  // namespace

std::vector<SweepPoint> massRatioSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  for (const double ratio : logGrid(1.0, 1e6, quick ? 7 : 13)) {
    points.push_back(headOn(backend, "heavy hits light", ratio, ratio, 1.0));
    points.push_back(headOn(backend, "light hits heavy", ratio, 1.0, ratio));
  }
  return points;
}

}  // namespace fooball::failure_map
