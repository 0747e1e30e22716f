#include "rapier/rapier_backend.h"

#include "host_files.h"
#include "node_backend.h"

namespace fooball {

namespace {

std::vector<OptionSpec> rapierOptionSpecs() {
  return {
      {"version",
       "Rapier 2D release (npm @dimforge/rapier2d-compat), both installed",
       0.0,
       0.0,
       1.0,
       true,
       OptionRole::Other,
       {"0.21.0", "0.19.3"}},
      {"num_solver_iterations",
       "Rapier solver iterations (substeps) per step (IntegrationParameters.numSolverIterations)",
       4.0, 1.0, 64.0, true, OptionRole::Iterations},
      {"num_internal_pgs_iterations",
       "Rapier PGS iterations within each solver iteration "
       "(IntegrationParameters.numInternalPgsIterations)",
       1.0, 1.0, 64.0, true},
      {"contact_natural_frequency",
       "Hz, stiffness of Rapier's soft contacts (IntegrationParameters.contact_natural_frequency; "
       "0: the release's own, 30)",
       0.0, 0.0, 10000.0},
      {"ccd", "Rapier continuous collision on every ball (RigidBodyDesc.setCcdEnabled)", 0.0, 0.0,
       1.0, true},
  };
}

constexpr JsEngine kRapier{"rapier", "rapier2d-0.21.0", &rapierOptionSpecs};

}  // namespace

std::unique_ptr<Backend> makeRapierBackend() {
  return makeNodeBackend(kRapier);
}

std::string rapierUnavailable() {
  std::string reason = node_host::unavailableReason(kRapier.package);
  return reason.empty() ? node_host::unavailableReason("rapier2d-0.19.3") : reason;
}

}  // namespace fooball
