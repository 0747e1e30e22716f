#pragma once

#include <btBulletDynamicsCommon.h>

#include <cstddef>
#include <memory>

namespace fooball::bullet_detail {

/// A btDiscreteDynamicsWorld with what every Bullet program builds it from (the HelloWorld
/// example's stack): the default collision configuration and dispatcher, the dynamic AABB-tree
/// broad phase and the sequential-impulse solver. Destroyed world first: it still touches its
/// objects (removing their broad-phase proxies), so they must outlive it (bullet_adapter.h).
///
/// One setting differs from that stack: the size of the dispatcher's pools. Bullet takes each
/// new pair's collision algorithm and persistent manifold from a pool of 4'096 (by default) and,
/// once that is used up, from the heap, freeing it when the pair's bounding boxes part. Every
/// ball pairs with every wall plane for good (wall_planes.h), so past ~1'000 balls the pools would
/// be full of wall pairs and every ball–ball pair that comes and goes would allocate in the step.
/// They are sized for the walls' 4 pairs a ball plus kBallPairsPerBall of its neighbours, below
/// 4'096 too: a world of 10 balls holds 80 pairs' pools (86 kB), not the default pools' 4.4 MB,
/// which every new world (each edit of a run that has stepped reloads it) allocated and wrote.
class BulletWorld {
 public:
  explicit BulletWorld(std::size_t ballCount);

  btDiscreteDynamicsWorld& get() { return *world_; }
  const btDiscreteDynamicsWorld& get() const { return *world_; }

 private:
  std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
};

/// Ball–ball pairs a ball may hold at once (bounding boxes overlapping, fattened by the broad
/// phase) before the pools overflow. Measured: the standard gas of 2'000 balls steps without a
/// single allocation in Bullet with 4 (tests/bullet_backend_test.cpp; 22'530 allocations in 60
/// steps with the default pools). A manifold is 880 bytes, so 10'000 balls hold 70 MB of them.
inline constexpr std::size_t kBallPairsPerBall = 4;

}  // namespace fooball::bullet_detail
