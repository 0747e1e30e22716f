#pragma once

#include <chipmunk/chipmunk.h>

namespace fooball::chipmunk_detail {

/// Category bits: walls and balls. Balls always collide with walls; with each other only while
/// WorldSettings::ballCollisions is on, which the mask turns off without touching the bodies.
/// Chipmunk rejects a pair in the broad phase when either shape's categories miss the other's
/// mask (cpShapeFilterReject), before any narrow-phase work or arbiter: collisions off cost no
/// ball–ball work beyond the bounding-box query.
inline constexpr cpBitmask kWallCategory = 0x1;
inline constexpr cpBitmask kBallCategory = 0x2;

inline cpShapeFilter wallFilter() {
  return cpShapeFilterNew(CP_NO_GROUP, kWallCategory, kBallCategory);
}

inline cpShapeFilter ballFilter(bool ballCollisions) {
  return cpShapeFilterNew(CP_NO_GROUP, kBallCategory,
                          ballCollisions ? (kWallCategory | kBallCategory) : kWallCategory);
}

/// Collision types, which select the handler that counts a contact (contact_counter.h).
inline constexpr cpCollisionType kBallType = 1;
inline constexpr cpCollisionType kWallType = 2;

}  // namespace fooball::chipmunk_detail
