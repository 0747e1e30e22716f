#pragma once

namespace fooball::bullet_detail {

/// Bullet's contact processing threshold, and the contacts it solves before they touch.
///
/// A Bullet contact point lives in a persistent manifold from the step it is found until its
/// distance exceeds the contact breaking threshold (btPersistentManifold::refreshContactPoints):
/// for a sphere 0.02 of its bounding disc, √3·r, so about 3.5% of the radius. Against a plane
/// (btConvexPlaneCollisionAlgorithm) a point is added while the ball is still that far away. The
/// solver turns every point whose distance is at most the manifold's contact processing threshold
/// into a contact row (btSequentialImpulseConstraintSolver::convertContact); the threshold is the
/// smaller of the two objects' (btCollisionObject::setContactProcessingThreshold), read when the
/// manifold is created, and defaults to BT_LARGE_FLOAT: every point, separated ones included. A
/// separated point at distance g > 0 gets the restitution target of a touching one less g/h (the
/// "speculative" part of setupContactConstraint), so a ball that meets a wall between two steps is
/// turned back early, at |u| − g/h instead of |u|, or stopped dead short of it, where it stays
/// (tests/bullet_backend_test.cpp: 0.3 m/s, 1 cm from a wall, stops 5 mm short; the "sticky walls"
/// of bulletphysics/bullet3#3094). A threshold of 0 solves only overlapping points, where the
/// restitution target is the exact elastic one; the overlap itself is then the split impulse's to
/// remove (split_impulse.h). Measured on the standard gas (docs/accuracy.md): with the
/// split-impulse threshold at 0 this is a loss of 3.5% in 10 s, and 0 here brings the change to
/// +0.099%; alone, beside the split impulse's gain, it changes +726% to +746%.
///
/// m, the default: every point, as Bullet's BT_LARGE_FLOAT (1e18 in the single-precision build).
/// Not that value itself, since the option is a double checked against its range and 1e18 + 1 is
/// 1e18: a manifold keeps no point farther apart than its breaking threshold, under 4% of a radius
/// of at most kMaxBoxSide (1e6 m), so any threshold beyond that solves exactly the points
/// BT_LARGE_FLOAT does, and 1e12 m is far beyond it.
inline constexpr double kDefaultContactProcessingThreshold = 1e12;

}  // namespace fooball::bullet_detail
