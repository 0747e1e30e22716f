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

constexpr double kCradleRadius = 0.1;  // m
constexpr double kCradleSpeed = 1.0;   // m/s
constexpr int kBalls = 5;
/// Where a touching row sits on the chart's log axis (gap / r).
constexpr double kTouchingDrawnAt = 1e-5;

/// The row with `gap` (m) between resting balls, run: its error, not yet its variant or parameter.
SweepPoint cradleRun(std::string_view backend, double gap) {
  Scene scene;
  scene.name = "cradle";
  scene.box = {6.0, 1.0};
  double x = 1.0;
  scene.balls.push_back({{x, 0.5}, {kCradleSpeed, 0.0}, kCradleRadius, diskMass(kCradleRadius)});
  x += 2.0 * kCradleRadius + 0.3 * kCradleRadius;  // the shooter starts 0.3 r short of the row
  for (int ball = 1; ball < kBalls; ++ball) {
    scene.balls.push_back({{x, 0.5}, {}, kCradleRadius, diskMass(kCradleRadius)});
    x += 2.0 * kCradleRadius + gap;
  }
  // The momentum crosses the row within 0.1 s; the last ball then flies ≤ 2.5 m before 2 s.
  const RunRecord run = runScene(scene, backend, 2.0);
  double error = length(run.velocities[kBalls - 1] - Vec2{kCradleSpeed, 0.0});
  for (int ball = 0; ball < kBalls - 1; ++ball)
    error += length(run.velocities[ball]);
  SweepPoint point;
  point.error = error / kCradleSpeed;
  point.scene = scene;
  return point;
}

}  // namespace

std::vector<SweepPoint> cradleSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  for (const double gapPerRadius : logGrid(1.0, 1e-4, quick ? 5 : 9)) {
    points.push_back(cradleRun(backend, gapPerRadius * kCradleRadius));
    points.back().parameter = gapPerRadius;
  }
  points.push_back(cradleRun(backend, 0.0));
  points.back().parameter = kTouchingDrawnAt;
  for (SweepPoint& point : points)
    point.variant = "gaps";
  return points;
}

}  // namespace fooball::failure_map
