#include "chipmunk_options.h"

#include "contact_slop.h"

namespace fooball::chipmunk_detail {

std::vector<OptionSpec> chipmunkOptionSpecs() {
  const ChipmunkSettings defaults;
  return {
      {"substeps", "Chipmunk steps per simulation step (each of dt/substeps seconds)",
       static_cast<double>(defaults.substeps), 1.0, 1000.0, true, OptionRole::Substeps},
      {"iterations", "Chipmunk impulse-solver iterations per Chipmunk step",
       static_cast<double>(defaults.iterations), 1.0, 100.0, true, OptionRole::Iterations},
      {"collision_slop",
       "overlap the position correction leaves alone, as a fraction of the smallest radius",
       defaults.collisionSlop, 0.0, kMaxSlopFraction},
      {"collision_bias",
       "fraction of an overlap (beyond the slop) still uncorrected after 1 s (1: no correction)",
       defaults.collisionBias, 0.0, 1.0},
      {"spatial_hash",
       "broad phase: 0 Chipmunk's bounding-box tree, 1 a spatial hash sized from the radii",
       defaults.spatialHash ? 1.0 : 0.0, 0.0, 1.0, true},
  };
}

ChipmunkSettings readChipmunkSettings(const OptionSet& options) {
  ChipmunkSettings settings;
  settings.substeps = static_cast<int>(options.value("substeps"));
  settings.iterations = static_cast<int>(options.value("iterations"));
  settings.collisionSlop = options.value("collision_slop");
  settings.collisionBias = options.value("collision_bias");
  settings.spatialHash = options.value("spatial_hash") != 0.0;
  return settings;
}

}  // namespace fooball::chipmunk_detail
