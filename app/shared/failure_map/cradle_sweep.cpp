// Newton's cradle: five equal balls in a row, the first shot at the other four. Hard spheres
// hit one pair at a time, so all the momentum ends in the last ball. A solver that resolves
// several touching contacts in one step (sequential impulses, a pass over overlapping pairs)
// shares it out instead whenever more than one contact falls in the same step.

#include <cmath>

#include "fooball/scene.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

constexpr double kRadius = 0.1;  // m
constexpr double kSpeed = 1.0;   // m/s
constexpr int kBalls = 5;
/// Where a touching row sits on the chart's log axis (gap / r).
constexpr double kTouchingDrawnAt = 1e-5;

double cradleError(std::string_view backend, double gap) {
  Scene scene;
  scene.name = "cradle";
  scene.box = {6.0, 1.0};
  double x = 1.0;
  scene.balls.push_back({{x, 0.5}, {kSpeed, 0.0}, kRadius, diskMass(kRadius)});
  x += 2.0 * kRadius + 0.3 * kRadius;  // the shooter starts 0.3 r short of the row
  for (int ball = 1; ball < kBalls; ++ball) {
    scene.balls.push_back({{x, 0.5}, {}, kRadius, diskMass(kRadius)});
    x += 2.0 * kRadius + gap;
  }
  // The momentum crosses the row within 0.1 s; the last ball then flies ≤ 2.5 m before 2 s.
  const RunRecord run = runScene(scene, backend, 2.0);
  double error = length(run.velocities[kBalls - 1] - Vec2{kSpeed, 0.0});
  for (int ball = 0; ball < kBalls - 1; ++ball)
    error += length(run.velocities[ball]);
  return error / kSpeed;
}

}  // namespace

std::vector<SweepPoint> cradleSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  for (const double gapPerRadius : logGrid(1.0, 1e-4, quick ? 5 : 9)) {
    points.push_back(
        measuredPoint("gaps", gapPerRadius, cradleError(backend, gapPerRadius * kRadius)));
  }
  points.push_back(measuredPoint("gaps", kTouchingDrawnAt, cradleError(backend, 0.0)));
  return points;
}

}  // namespace fooball::failure_map
