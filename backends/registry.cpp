#include "registry.h"

#include <stdexcept>
#include <string>

#include "box2d/box2d_backend.h"
#include "box2d3/box2d3_backend.h"
#include "bullet/bullet_backend.h"
#include "chipmunk/chipmunk_backend.h"
#include "elastic/elastic_backend.h"
#include "exact/exact_backend.h"
#include "matter/matter_backend.h"
#include "rapier/rapier_backend.h"
#include "xpbd/xpbd_backend.h"

namespace fooball {

namespace {

constexpr BackendInfo kBackends[] = {
    {"elastic", "time-stepped elastic solver: move, detect overlaps, separate, exchange impulses",
     &makeElasticBackend, kElasticLimits},
    {"box2d", "Box2D 2.4.1, restitution 1, configured for frictionless balls", &makeBox2dBackend,
     kBox2dLimits},
    {"exact", "event-driven solver: exact collision times, processed in order", &makeExactBackend,
     kExactLimits},
    {"xpbd", "small-steps position-based dynamics: predict, project contacts, restitution pass",
     &makeXpbdBackend, kXpbdLimits},
    {"chipmunk", "Chipmunk2D 7.0.3, elasticity 1, configured for frictionless balls",
     &makeChipmunkBackend, kChipmunkLimits},
    {"bullet", kBulletDescription, &makeBulletBackend, kBulletLimits},
    {"matter", "matter.js 0.20.0 (JavaScript, in Node.js), restitution 1, as its users set it up",
     &makeMatterBackend, kMatterLimits, &matterUnavailable, "JavaScript"},
    {"rapier",
     "Rapier 2D 0.21.0 or 0.19.3 (WebAssembly, in Node.js), restitution 1, as its users set it up",
     &makeRapierBackend, kRapierLimits, &rapierUnavailable, "WebAssembly"},
    {"box2d3",
     "Box2D v3 (box2d3-wasm 5.2.0: WebAssembly, in Node.js), restitution 1, as its users set it up",
     &makeBox2d3Backend, kBox2d3Limits, &box2d3Unavailable, "WebAssembly"},
};

}  // namespace

std::span<const BackendInfo> registeredBackends() {
  return kBackends;
}

std::string unavailableReason(const BackendInfo& info) {
  return info.unavailable != nullptr ? info.unavailable() : std::string();
}

const BackendInfo& backendInfo(std::string_view name) {
  for (const BackendInfo& info : kBackends) {
    if (info.name == name) return info;
  }
  std::string known;
  for (const BackendInfo& info : kBackends) {
    known += known.empty() ? "" : ", ";
    known += info.name;
  }
  throw std::invalid_argument("unknown backend '" + std::string(name) + "' (known: " + known + ")");
}

std::unique_ptr<Backend> createBackend(std::string_view name) {
  return backendInfo(name).create();
}

std::unique_ptr<Backend> createBackend(const RunSpec& spec) {
  try {
    std::unique_ptr<Backend> backend = createBackend(spec.backend);
    for (const std::string& assignment : spec.assignments)
      backend->setOptionFromText(assignment);
    return backend;
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("run spec '" + spec.text() + "': " + error.what());
  }
}

}  // namespace fooball
