#pragma once

#include <box2d/b2_fixture.h>

namespace fooball::box2d_detail {

/// The material of every ball and wall: perfectly elastic, frictionless.
/// - restitution 1: Box2D mixes max(a, b), so 1 on either side would do; both say it.
/// - restitutionThreshold 0: Box2D only applies restitution when the approach speed exceeds the
///   threshold (default 1 m/s), so slow hits would be perfectly inelastic. It mixes min(a, b);
///   set on balls *and* walls so no pairing brings the default back.
/// - friction 0: frictionless balls; a tangential impulse would also be the only thing able to
///   spin a ball (rotation is fixed anyway).
inline b2FixtureDef elasticFixtureDef(const b2Shape& shape, float density, b2Filter filter) {
  b2FixtureDef def;
  def.shape = &shape;
  def.density = density;
  def.friction = 0.0f;
  def.restitution = 1.0f;
  def.restitutionThreshold = 0.0f;
  def.filter = filter;
  return def;
}

}  // namespace fooball::box2d_detail
