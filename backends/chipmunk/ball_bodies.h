#pragma once

#include <chipmunk/chipmunk.h>

#include "chipmunk_space.h"
#include "fooball/scene.h"

namespace fooball::chipmunk_detail {

/// One ball: a dynamic body with one circle shape.
struct BallBody {
  cpBody* body = nullptr;
  cpShape* shape = nullptr;
};

/// Creates a ball with only what a ball needs:
/// - mass: the scene's, set on the body (cpBodyNew), not derived from the shape's density, so it
///   is the scene's double exactly;
/// - moment INFINITY: no rotation. Chipmunk has no fixed-rotation flag; an infinite moment gives
///   i_inv = 0, so no impulse can spin the ball and no angular state takes energy (its sanity
///   check only rejects NaN moments: ∞ passes, and m > 0, i > 0 holds);
/// - no sleeping: the space's sleep threshold stays at its default INFINITY (chipmunk_adapter.cpp
///   sets it explicitly), so a ball never freezes and ignores drag and tools.
BallBody createBall(Space& space, const BallDef& ball, bool ballCollisions);

/// Gives the ball radius `radius` (m) and mass `mass` (kg). The radius is changed in place with
/// cpCircleShapeSetRadius (chipmunk_unsafe.h: "unsafe" because Chipmunk would not update a mass
/// derived from the shape, and none is here) and the shape reindexed.
void setBallShape(Space& space, const BallBody& ball, double radius, double mass);

/// Sets the ball's collision filter: ball–ball collisions on or off (collision_filter.h).
void setBallCollisions(const BallBody& ball, bool ballCollisions);

}  // namespace fooball::chipmunk_detail
