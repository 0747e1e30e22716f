#include "boundary.h"

#include <algorithm>

namespace fooball::failure_map {

std::vector<Boundary> locateBoundaries(const SweepSpec& spec, std::span<const SweepPoint> points) {
  std::vector<Boundary> boundaries;
  for (const SweepPoint& point : points) {
    const bool known = std::any_of(boundaries.begin(), boundaries.end(), [&](const Boundary& b) {
      return b.backend == point.backend && b.variant == point.variant;
    });
    if (known) continue;
    std::vector<const SweepPoint*> curve;
    for (const SweepPoint& other : points) {
      if (other.backend == point.backend && other.variant == point.variant) curve.push_back(&other);
    }
    std::sort(curve.begin(), curve.end(), [&](const SweepPoint* a, const SweepPoint* b) {
      return spec.harderAbove ? a->parameter < b->parameter : a->parameter > b->parameter;
    });
    Boundary boundary{point.backend, point.variant, {}, {}, false};
    for (const SweepPoint* step : curve) {
      if (!boundary.firstFail) {
        if (step->passed)
          boundary.lastPass = step->parameter;
        else
          boundary.firstFail = step->parameter;
      } else if (step->passed) {
        boundary.passesAgain = true;
      }
    }
    boundaries.push_back(std::move(boundary));
  }
  return boundaries;
}

}  // namespace fooball::failure_map
