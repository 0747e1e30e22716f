// Tunnelling: a time-stepped solver sees contacts only at the end of each solver step. A ball
// moving v·h per step (h = dt/substeps) towards a resting ball of the same radius r finds it
// only if some step ends with the centres closer than 2r *and not yet past each other*: a window
// 2r long. Below v·h = 2r a step always ends in it; above 4r (the whole overlap zone) none can;
// in between it depends on where the steps fall. Walls are half-planes in elastic and exact and
// 8 m slabs in Box2D, so a step that ends past a wall's surface is still seen.

#include <cmath>
#include <memory>
#include <string>

#include "fooball/scene.h"
#include "registry.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

/// Gap between the shooter's surface and its target at the start, in radii: no special phase.
constexpr double kStartGap = 0.37;

std::string radiusText(double radius) {
  return radius < 0.1 ? "0.05" : "0.5";
}

/// s: whole steps enough for the shooter to cover the gap and the whole target, plus two.
double flightTime(double radius, double speed) {
  return (std::ceil((kStartGap + 4.0) * radius / (speed * kFrameDt)) + 2.0) * kFrameDt;
}

/// A ball of radius `radius` at `speed` towards a resting twin: afterwards the shooter rests
/// and the target moves at `speed` (equal masses, head on).
SweepPoint ballTarget(std::string_view backend, double radius, double speed) {
  const double time = flightTime(radius, speed);
  const double shooterX = 2.0 * radius;
  const double targetX = shooterX + (2.0 + kStartGap) * radius;
  Scene scene;
  scene.name = "tunnelling";
  // Long enough that the target, at `speed` for the whole run, stays clear of the right wall.
  scene.box = {targetX + speed * time + 4.0 * radius, 4.0 * radius};
  const double mass = diskMass(radius);
  scene.balls = {{{shooterX, 2.0 * radius}, {speed, 0.0}, radius, mass},
                 {{targetX, 2.0 * radius}, {}, radius, mass}};
  const RunRecord run = runScene(scene, backend, time);
  SweepPoint point;
  point.scene = scene;
  point.error = (length(run.velocities[0]) + length(run.velocities[1] - Vec2{speed, 0.0})) / speed;
  return point;
}

/// A ball of radius `radius` at `speed` towards the right wall: afterwards it moves at −speed.
SweepPoint wallTarget(std::string_view backend, double radius, double speed) {
  const double time = flightTime(radius, speed);
  Scene scene;
  scene.name = "tunnelling";
  // Room on the left for the whole run after the bounce.
  const double width = speed * time + 4.0 * radius;
  scene.box = {width, 4.0 * radius};
  scene.balls = {
      {{width - (1.0 + kStartGap) * radius, 2.0 * radius}, {speed, 0.0}, radius, diskMass(radius)}};
  const RunRecord run = runScene(scene, backend, time);
  SweepPoint point;
  point.scene = scene;
  point.error = length(run.velocities[0] - Vec2{-speed, 0.0}) / speed;
  if (run.escaped > 0) point.error = 2.0;  // gone through the wall, whatever its velocity
  return point;
}

}  // namespace

std::vector<SweepPoint> tunnellingSweep(std::string_view backend, bool quick) {
  const double step = solverStep(*createBackend(backend), kFrameDt);
  // v·h/r from 1/2 to 16 in steps of 2^(1/4) (2^(1/2) quick): the 2r–4r window and a margin.
  const std::vector<double> reach = logGrid(0.5, 16.0, quick ? 11 : 21);
  std::vector<SweepPoint> points;
  for (const double radius : quick ? std::vector{0.05} : std::vector{0.05, 0.5}) {
    for (const double perStep : reach) {
      const double speed = perStep * radius / step;
      SweepPoint point = ballTarget(backend, radius, speed);
      point.variant = "ball r=" + radiusText(radius) + " m";
      point.parameter = perStep;
      points.push_back(std::move(point));
    }
  }
  for (const double perStep : reach) {
    constexpr double kRadius = 0.05;
    SweepPoint point = wallTarget(backend, kRadius, perStep * kRadius / step);
    point.variant = "wall r=" + radiusText(kRadius) + " m";
    point.parameter = perStep;
    points.push_back(std::move(point));
  }
  return points;
}

}  // namespace fooball::failure_map
