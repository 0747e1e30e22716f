#pragma once

#include <box2d/b2_world.h>

#include <memory>

#include "fooball/scene.h"

namespace fooball::benchmarks {

/// A scene built straight on Box2D 2.4.1 the way a typical user would, as the baseline the
/// Box2D backend is measured against: a b2World, one dynamic body with a circle fixture per
/// ball, restitution 1 and restitution threshold 0 on every fixture, and Box2D's defaults
/// otherwise — friction 0.2, rotation on, sleeping on, continuous collision against static
/// bodies, 8 velocity and 3 position iterations. The walls that are on are two-sided edges of
/// one static body. What the backend saves against this is what modelling only what balls need
/// saves; what it loses is what the adapter costs.
class RawBox2dWorld {
 public:
  explicit RawBox2dWorld(const Scene& scene);

  /// `substeps` Box2D steps of dt/substeps each.
  void step(double dt, int substeps);

 private:
  std::unique_ptr<b2World> world_;
};

}  // namespace fooball::benchmarks
