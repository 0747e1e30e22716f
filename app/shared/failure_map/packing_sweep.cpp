// Dense packing: a gas on a triangular lattice (the densest packing of discs, φ = π/√12 ≈ 0.907
// when they touch), every ball at 1 m/s in its own direction. As φ grows the gaps shrink to
// less than a step's travel, so a time-stepped solver meets several contacts per step and
// leaves overlaps, and an event-driven one handles ever more events per step.

#include <cmath>
#include <numbers>

#include "fooball/scene.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

constexpr double kPackingSpeed = 1.0;  // m/s

/// `side` × `side` balls on a triangular lattice of packing fraction `fraction` (< π/√12); the
/// margin to the walls makes the box's own fraction a little lower.
Scene latticeGas(double radius, double fraction, int side) {
  // A lattice cell of pitch a holds one ball in (√3/2)·a² of area.
  const double pitch =
      std::sqrt(std::numbers::pi * radius * radius / fraction * 2.0 / std::sqrt(3.0));
  const double rowHeight = pitch * std::sqrt(3.0) / 2.0;
  Scene scene;
  scene.name = "packing";
  // Half a pitch (≥ r) between the outermost balls and the walls.
  scene.box = {(side + 0.5) * pitch, (side - 1) * rowHeight + pitch};
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      // Odd rows sit half a pitch over.
      const double x = (column + (row % 2 == 0 ? 0.5 : 1.0)) * pitch;
      const double y = row * rowHeight + 0.5 * pitch;
      const auto index = static_cast<std::size_t>(row * side + column);
      scene.balls.push_back(
          {{x, y}, kPackingSpeed * spreadDirection(index), radius, diskMass(radius)});
    }
  }
  return scene;
}

}  // namespace

std::vector<SweepPoint> packingSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  const std::vector<double> fractions =
      quick ? std::vector{0.3, 0.5, 0.7, 0.84, 0.89}
            : std::vector{0.3, 0.4, 0.5, 0.6, 0.7, 0.75, 0.8, 0.84, 0.87, 0.89};
  const int side = quick ? 8 : 12;
  const double seconds = quick ? 1.0 : 2.0;
  // Two radii: Box2D leaves contacts up to its linear slop (0.005 m) deep, 5% of 0.1 m.
  for (const double radius : {0.1, 0.2}) {
    for (const double fraction : fractions) {
      const Scene scene = latticeGas(radius, fraction, side);
      const double boxFraction = static_cast<double>(scene.balls.size()) * std::numbers::pi *
                                 radius * radius / (scene.box.width * scene.box.height);
      const RunRecord run = runScene(scene, backend, seconds);
      points.push_back(measuredPoint(
          scene, std::to_string(side * side) + " balls r=" + (radius < 0.15 ? "0.1" : "0.2") + " m",
          boxFraction, run.energyError, run.maxOverlap));
    }
  }
  return points;
}

}  // namespace fooball::failure_map
