#pragma once

#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <memory>

#include "box2d/wall_bodies.h"
#include "fooball/scene.h"

namespace fooball::benchmarks {

/// The Box2D backend's own world without the adapter around it, as the baseline the adapter's
/// overhead is counted against: the same ball bodies (box2d/ball_bodies.h: fixed rotation, no
/// sleeping, frictionless, restitution 1), the same wall pieces (box2d/wall_bodies.h) with their
/// corner contacts dropped (box2d/seam_contacts.h), the same iterations, stepped with
/// b2World::Step alone — no state read-out, collision counting, wall containment or substep
/// checks. The same physics, so what the backend costs beyond this is what the adapter costs.
class BareBox2dWorld {
 public:
  explicit BareBox2dWorld(const Scene& scene);

  /// `substeps` Box2D steps of dt/substeps each.
  void step(double dt, int substeps);

 private:
  /// The one part of the backend's contact listener that is physics, not bookkeeping.
  class SeamListener final : public b2ContactListener {
    void PreSolve(b2Contact* contact, const b2Manifold* oldManifold) override;
  };

  SeamListener seams_;  ///< declared before world_, which holds a pointer to it
  std::unique_ptr<b2World> world_;
  box2d_detail::WallBodies walls_;
};

}  // namespace fooball::benchmarks
