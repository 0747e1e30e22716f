#include "matter/matter_backend.h"

#include "host_files.h"
#include "node_backend.h"

namespace fooball {

namespace {

std::vector<OptionSpec> matterOptionSpecs() {
  return {
      {"position_iterations",
       "matter.js position-solver passes per step (Engine.positionIterations; its default)", 6.0,
       1.0, 100.0, true},
      {"velocity_iterations",
       "matter.js velocity-solver passes per step (Engine.velocityIterations; its default)", 4.0,
       1.0, 100.0, true, OptionRole::Iterations},
      {"resting_thresh",
       "normal speed in px per 1/60 s frame (64 px/m) below which a contact is solved as resting, "
       "not bounced (Resolver._restingThresh; 0 makes every hit elastic)",
       2.0, 0.0, 100.0},
      {"slop", "overlap in px left alone by the position solver (Body.slop; 64 px/m)", 0.05, 0.0,
       6.4},
  };
}

constexpr JsEngine kMatter{"matter", "matter-js", &matterOptionSpecs};

}  // namespace

std::unique_ptr<Backend> makeMatterBackend() {
  return makeNodeBackend(kMatter);
}

std::string matterUnavailable() {
  return node_host::unavailableReason(kMatter.package);
}

}  // namespace fooball
