#pragma once

#include <btBulletDynamicsCommon.h>

#include <array>
#include <memory>

#include "contact_counter.h"
#include "fooball/scene.h"

namespace fooball::bullet_detail {

/// The walls that are on, as static planes (btStaticPlaneShape), the shape Bullet users give a
/// ground: one per side, its normal into the box, through the box edge. Walls that are off do not
/// exist, so Bullet does no work for them.
///
/// A plane is a half-space to Bullet's sphere–plane test (btConvexPlaneCollisionAlgorithm: the
/// distance is the sphere's lowest point along the normal less the plane's offset), so a ball
/// whose centre a step carried past the edge is still pushed back into the box, never out on the
/// far side: a wall cannot be tunnelled. Its bounding box is unbounded, so every ball pairs with
/// every plane for as long as both exist (bullet_world.h sizes the pools for that).
class WallPlanes {
 public:
  /// Creates the walls `walls` turns on and removes those it turns off, leaving the others (and
  /// their contacts) alone. `contactProcessingThreshold` (m) applies to walls created now.
  void sync(btDiscreteDynamicsWorld& world, const Box& box, const Walls& walls,
            float contactProcessingThreshold, ContactCounts* counts);

  /// Drops the walls without removing them from their world, which is already destroyed.
  void forget();

 private:
  struct Wall {
    std::unique_ptr<btStaticPlaneShape> shape;
    std::unique_ptr<btRigidBody> body;
  };
  std::array<Wall, 4> walls_;  ///< left, right, bottom, top; empty when off
};

}  // namespace fooball::bullet_detail
