#pragma once

namespace fooball::bullet_detail {

/// Collision filter groups: walls and balls. Balls always collide with walls; with each other
/// only while WorldSettings::ballCollisions is on. Bullet rejects a pair in the broad phase when
/// either object's group misses the other's mask (btOverlappingPairCache's
/// needsBroadphaseCollision) before any narrow-phase work or manifold: collisions off cost no
/// ball–ball work beyond the tree query. The filter is read when a pair is created, so a change of
/// ballCollisions rebuilds the world (bullet_adapter.cpp) rather than leave existing pairs
/// colliding.
inline constexpr int kWallGroup = 0x1;
inline constexpr int kBallGroup = 0x2;

inline constexpr int kWallMask = kBallGroup;

inline constexpr int ballMask(bool ballCollisions) {
  return ballCollisions ? (kWallGroup | kBallGroup) : kWallGroup;
}

}  // namespace fooball::bullet_detail
