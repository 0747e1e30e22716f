#include "bullet_world.h"

#include <algorithm>
#include <limits>

namespace fooball::bullet_detail {

namespace {

btDefaultCollisionConstructionInfo poolsFor(std::size_t ballCount) {
  constexpr std::size_t kWallPlanes = 4;
  btDefaultCollisionConstructionInfo info;
  // One ball's pairs at least: Bullet's pools need an element.
  const std::size_t pairs = std::max<std::size_t>(ballCount, 1) * (kWallPlanes + kBallPairsPerBall);
  const auto size = static_cast<int>(
      std::min<std::size_t>(pairs, static_cast<std::size_t>(std::numeric_limits<int>::max())));
  info.m_defaultMaxPersistentManifoldPoolSize = size;
  info.m_defaultMaxCollisionAlgorithmPoolSize = size;
  return info;
}

}  // namespace

BulletWorld::BulletWorld(std::size_t ballCount)
    : configuration_(std::make_unique<btDefaultCollisionConfiguration>(poolsFor(ballCount))),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), configuration_.get())) {}

}  // namespace fooball::bullet_detail
