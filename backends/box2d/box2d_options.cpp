#include "box2d_options.h"

namespace fooball::box2d_detail {

std::vector<OptionSpec> box2dOptionSpecs() {
  const Box2dSettings defaults;
  return {
      {"substeps", "Box2D steps per simulation step (each of dt/substeps seconds)",
       static_cast<double>(defaults.substeps), 1.0, 1000.0, true, OptionRole::Substeps},
      {"velocity_iterations", "Box2D velocity (impulse) iterations per Box2D step",
       static_cast<double>(defaults.velocityIterations), 1.0, 100.0, true, OptionRole::Iterations},
      {"position_iterations", "Box2D position-correction iterations per Box2D step (0: none)",
       static_cast<double>(defaults.positionIterations), 0.0, 100.0, true},
      {"bullets", "continuous collision between balls too (0/1; walls always have it)",
       defaults.bullets ? 1.0 : 0.0, 0.0, 1.0, true},
      {"auto_substeps",
       "raise substeps for a step when a ball would move more than Box2D's 2 m per step cap (0/1)",
       defaults.autoSubsteps ? 1.0 : 0.0, 0.0, 1.0, true},
  };
}

Box2dSettings readBox2dSettings(const OptionSet& options) {
  Box2dSettings settings;
  settings.substeps = static_cast<int>(options.value("substeps"));
  settings.velocityIterations = static_cast<int>(options.value("velocity_iterations"));
  settings.positionIterations = static_cast<int>(options.value("position_iterations"));
  settings.bullets = options.value("bullets") != 0.0;
  settings.autoSubsteps = options.value("auto_substeps") != 0.0;
  return settings;
}

}  // namespace fooball::box2d_detail
