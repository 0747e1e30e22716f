#include "bullet_options.h"

#include "fooball/scene.h"

namespace fooball::bullet_detail {

static_assert(kDefaultContactProcessingThreshold > 1e3 * kMaxBoxSide,
              "the default contact processing threshold solves every point (contact_processing.h)");

std::vector<OptionSpec> bulletOptionSpecs() {
  const BulletSettings defaults;
  return {
      // At most 100: a Bullet step shorter than FLT_EPSILON seconds (1.2e-7) is no step at all
      // (stepSimulation takes a time step that btFuzzyZero calls zero as nothing to do), and
      // 100 substeps of the shortest step the tools use (1e-4 s) stay ten times above it.
      {"substeps", "Bullet steps per simulation step (each of dt/substeps seconds)",
       static_cast<double>(defaults.substeps), 1.0, 100.0, true, OptionRole::Substeps},
      {"solver_iterations", "sequential-impulse iterations per Bullet step (m_numIterations)",
       static_cast<double>(defaults.solverIterations), 1.0, 100.0, true, OptionRole::Iterations},
      {"split_impulse_penetration_threshold",
       "m, overlaps shallower than this are pushed apart with real velocity (Bullet: -0.04; 0: "
       "none)",
       defaults.splitImpulsePenetrationThreshold, -1e6, 0.0},
      {"contact_processing_threshold",
       "m, contact points farther apart than this are not solved (default: every point; 0: "
       "only overlapping ones)",
       defaults.contactProcessingThreshold, 0.0, kDefaultContactProcessingThreshold},
      {"warm_starting",
       "fraction of each contact's last impulse it starts the next solve with (Bullet: 0.85)",
       defaults.warmStarting, 0.0, 1.0},
  };
}

BulletSettings readBulletSettings(const OptionSet& options) {
  BulletSettings settings;
  settings.substeps = static_cast<int>(options.value("substeps"));
  settings.solverIterations = static_cast<int>(options.value("solver_iterations"));
  settings.splitImpulsePenetrationThreshold = options.value("split_impulse_penetration_threshold");
  settings.contactProcessingThreshold = options.value("contact_processing_threshold");
  settings.warmStarting = options.value("warm_starting");
  return settings;
}

}  // namespace fooball::bullet_detail
