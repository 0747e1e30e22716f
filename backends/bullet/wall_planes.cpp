#include "wall_planes.h"

#include "collision_filter.h"
#include "elastic_material.h"

namespace fooball::bullet_detail {

namespace {

enum Side { kLeft, kRight, kBottom, kTop, kSideCount };

/// The plane n·x = offset of one side, n pointing into the box.
std::unique_ptr<btStaticPlaneShape> planeOf(Side side, const Box& box) {
  const auto width = static_cast<float>(box.width);
  const auto height = static_cast<float>(box.height);
  switch (side) {
    case kLeft:
      return std::make_unique<btStaticPlaneShape>(btVector3(1.0f, 0.0f, 0.0f), 0.0f);
    case kRight:
      return std::make_unique<btStaticPlaneShape>(btVector3(-1.0f, 0.0f, 0.0f), -width);
    case kBottom:
      return std::make_unique<btStaticPlaneShape>(btVector3(0.0f, 1.0f, 0.0f), 0.0f);
    default:
      return std::make_unique<btStaticPlaneShape>(btVector3(0.0f, -1.0f, 0.0f), -height);
  }
}

}  // namespace

void WallPlanes::sync(btDiscreteDynamicsWorld& world, const Box& box, const Walls& walls,
                      float contactProcessingThreshold, ContactCounts* counts) {
  const std::array<bool, 4> on = {walls.left, walls.right, walls.bottom, walls.top};
  for (int side = kLeft; side < kSideCount; ++side) {
    Wall& wall = walls_[static_cast<std::size_t>(side)];
    if (on[static_cast<std::size_t>(side)] && wall.body == nullptr) {
      wall.shape = planeOf(static_cast<Side>(side), box);
      // Mass 0: static.
      const btRigidBody::btRigidBodyConstructionInfo info(0.0f, nullptr, wall.shape.get());
      wall.body = std::make_unique<btRigidBody>(info);
      makeElastic(*wall.body);
      wall.body->setContactProcessingThreshold(contactProcessingThreshold);
      constexpr common::WallBit bits[] = {common::kLeftWall, common::kRightWall,
                                          common::kBottomWall, common::kTopWall};
      tagWall(*wall.body, counts, bits[side]);
      world.addRigidBody(wall.body.get(), kWallGroup, kWallMask);
    } else if (!on[static_cast<std::size_t>(side)] && wall.body != nullptr) {
      world.removeRigidBody(wall.body.get());
      wall.body.reset();
      wall.shape.reset();
    }
  }
}

void WallPlanes::forget() {
  walls_ = {};
}

}  // namespace fooball::bullet_detail
