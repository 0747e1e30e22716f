#include "box2d3/box2d3_backend.h"

#include "host_files.h"
#include "node_backend.h"

namespace fooball {

namespace {

// The options, in one place; the adapter (backends/js/adapters/box2d3.js) reads them by name.
// Defaults are Box2D v3's own (b2DefaultWorldDef), but for the restitution threshold, which its
// users set to 0 for restitution 1.
std::vector<OptionSpec> box2d3OptionSpecs() {
  return {
      // Solver iterations in FooBall's sense (as Rapier's num_solver_iterations): Box2D v3 finds
      // contacts, and takes each contact's approach speed for restitution, once per step; its
      // sub-steps only solve them again (docs/accuracy.md).
      {"substeps", "Box2D v3 sub-steps per step (b2World_Step's subStepCount; its samples' 4)", 4.0,
       1.0, 64.0, true, OptionRole::Iterations},
      {"restitution_threshold",
       "m/s, approach speed below which Box2D v3 applies no restitution "
       "(b2WorldDef.restitutionThreshold; its default 1, 0 as its users set it for restitution 1)",
       0.0, 0.0, 100.0},
      {"contact_hertz",
       "Hz, stiffness of Box2D v3's soft contacts (b2World_SetContactTuning's contactHertz)", 30.0,
       0.01, 10000.0},
      {"contact_damping_ratio",
       "damping ratio of Box2D v3's soft contacts (b2World_SetContactTuning's dampingRatio)", 10.0,
       0.0, 1000.0},
      {"push_out_speed",
       "m/s, the most Box2D v3 pushes overlapping shapes apart "
       "(b2World_SetContactTuning's pushSpeed, b2WorldDef.contactPushMaxVelocity)",
       3.0, 0.0, 1000.0},
      {"warm_starting", "Box2D v3 warm starting of contact impulses (b2World_EnableWarmStarting)",
       1.0, 0.0, 1.0, true},
      {"continuous",
       "Box2D v3 continuous collision of balls against walls (b2World_EnableContinuous)", 1.0, 0.0,
       1.0, true},
  };
}

constexpr JsEngine kBox2d3{"box2d3", "box2d3-wasm", &box2d3OptionSpecs};

}  // namespace

std::unique_ptr<Backend> makeBox2d3Backend() {
  return makeNodeBackend(kBox2d3);
}

std::string box2d3Unavailable() {
  return node_host::unavailableReason(kBox2d3.package);
}

}  // namespace fooball
