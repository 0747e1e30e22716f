// Resting pile: 22 balls stacked in four touching rows on the floor of a box just as wide as
// the bottom row, at rest. Exactly, nothing moves. Under gravity a time-stepped solver lets
// each ball fall g·h² per step into the one below and pushes it back out, which can pump
// energy in (elastic impulses on a contact that closes every step); an event-driven solver
// meets an endless series of ever smaller bounces (a Zeno pile) unless a rest rule stops it (the
// exact solver's ball_rest_time, on by default), so the pile runs at the backends' defaults,
// without the map's event cap.

#include <cmath>

#include "fooball/scene.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

constexpr double kPileRadius = 0.1;  // m
constexpr int kRows = 4;
constexpr int kBottomRow = 6;  ///< balls; rows alternate 6 and 5

Scene pile(double gravity) {
  Scene scene;
  scene.name = "pile";
  scene.box = {2.0 * kPileRadius * kBottomRow, 20.0 * kPileRadius};
  scene.world.gravity = {0.0, -gravity};
  for (int row = 0; row < kRows; ++row) {
    const bool shifted = row % 2 == 1;
    const double y =
        kPileRadius + row * std::sqrt(3.0) * kPileRadius;  // rows touch their neighbours
    for (int column = 0; column < kBottomRow - (shifted ? 1 : 0); ++column) {
      const double x = (shifted ? 2.0 : 1.0) * kPileRadius + 2.0 * kPileRadius * column;
      scene.balls.push_back({{x, y}, {}, kPileRadius, diskMass(kPileRadius)});
    }
  }
  return scene;
}

}  // namespace

std::vector<SweepPoint> pileSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  for (const double gravity : logGrid(1.0, 1000.0, quick ? 4 : 7)) {
    const Scene scene = pile(gravity);
    double energyScale = 0.0;  // J, Σ m·g·r: every ball lifted by its radius
    for (const BallDef& ball : scene.balls)
      energyScale += ball.mass * gravity * ball.radius;
    const RunRecord run = runScene(scene, backend, quick ? 1.0 : 2.0, kFrameDt, EventCap::Default);
    points.push_back(measuredPoint(scene, std::to_string(scene.balls.size()) + " balls", gravity,
                                   run.energyDrift / energyScale, run.maxOverlap));
  }
  return points;
}

}  // namespace fooball::failure_map
