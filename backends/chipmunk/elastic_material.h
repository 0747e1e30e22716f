#pragma once

#include <chipmunk/chipmunk.h>

namespace fooball::chipmunk_detail {

/// The material of every ball and wall: perfectly elastic, frictionless.
/// - elasticity 1 on both: Chipmunk combines the two shapes' values as a *product*
///   (cpArbiterUpdate: arb->e = a->e * b->e), not Box2D's max, so a wall left at the default 0
///   would make every wall bounce perfectly inelastic. 1 × 1 = 1.
/// - friction 0: also a product (arb->u = a->u * b->u), so 0 on either side would do; both say
///   it. A tangential impulse would only try to spin a ball whose moment is infinite
///   (ball_bodies.h), and it would take energy at every glancing contact.
/// Chipmunk has no restitution threshold (Box2D's trap): cpArbiterPreStep sets the target
/// bounce to e times the approach speed at any speed.
inline void makeElastic(cpShape* shape) {
  cpShapeSetElasticity(shape, 1.0);
  cpShapeSetFriction(shape, 0.0);
}

}  // namespace fooball::chipmunk_detail
