#include "xpbd_options.h"

namespace fooball::xpbd {

std::vector<OptionSpec> xpbdOptionSpecs() {
  const XpbdSettings defaults;
  return {
      {"substeps", "solver substeps per step (more: less tunnelling and overlap)",
       static_cast<double>(defaults.substeps), 1, 1000, true, OptionRole::Substeps},
      {"iterations",
       "Gauss–Seidel sweeps per substep of the contact projection and of the velocity pass (more: "
       "less energy error where contacts share a ball)",
       static_cast<double>(defaults.iterations), 1, 100, true, OptionRole::Iterations},
  };
}

XpbdSettings readXpbdSettings(const OptionSet& options) {
  XpbdSettings settings;
  settings.substeps = static_cast<int>(options.value("substeps"));
  settings.iterations = static_cast<int>(options.value("iterations"));
  return settings;
}

}  // namespace fooball::xpbd
