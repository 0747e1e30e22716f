#pragma once

#include <string>

#include "fooball/scene.h"

namespace fooball::failure_map {

/// One scene of a sweep run on one backend: where it sits on the sweep's parameter axis, the
/// errors it made and whether they stay within the sweep's limits (SweepSpec).
struct SweepPoint {
  std::string sweep;    ///< e.g. "tunnelling"
  std::string backend;  ///< registry name
  std::string variant;  ///< the fixed settings of one curve, e.g. "ball r=0.05 m"
  double parameter = 0.0;
  double error = 0.0;       ///< the sweep's error metric (SweepSpec::errorName); NaN fails
  double maxOverlap = 0.0;  ///< deepest overlap seen, fraction of the smaller radius
  bool passed = false;
  Scene scene;  ///< the scene as run (the app opens it when its point is clicked)
};

}  // namespace fooball::failure_map
