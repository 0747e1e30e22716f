#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sweep_point.h"

/// The six sweeps of the failure map, one file each. Each runs its grid of scenes on `backend`
/// and fills parameter, variant, error and maxOverlap of every point; failure_map.cpp names the
/// points and judges them. `quick` runs a coarser grid and shorter scenes.
namespace fooball::failure_map {

/// A point as a sweep measures it; runSweep adds the sweep, the backend and the verdict.
inline SweepPoint measuredPoint(const Scene& scene, std::string variant, double parameter,
                                double error, double maxOverlap = 0.0) {
  SweepPoint point;
  point.scene = scene;
  point.variant = std::move(variant);
  point.parameter = parameter;
  point.error = error;
  point.maxOverlap = maxOverlap;
  return point;
}

/// A ball shot at a resting ball (and at a wall) faster and faster: v·h/r, h the solver step.
std::vector<SweepPoint> tunnellingSweep(std::string_view backend, bool quick);
/// A head-on hit between masses M and m, M/m growing: outgoing velocities against closed form.
std::vector<SweepPoint> massRatioSweep(std::string_view backend, bool quick);
/// Newton's cradle of five balls with shrinking gaps, down to touching.
std::vector<SweepPoint> cradleSweep(std::string_view backend, bool quick);
/// A gas on a triangular lattice, packing fraction rising towards the lattice's 0.907.
std::vector<SweepPoint> packingSweep(std::string_view backend, bool quick);
/// One gas scaled from millimetres to kilometres (radii, box and speeds alike).
std::vector<SweepPoint> scaleSweep(std::string_view backend, bool quick);
/// A resting pile of balls under stronger and stronger gravity.
std::vector<SweepPoint> pileSweep(std::string_view backend, bool quick);

}  // namespace fooball::failure_map
