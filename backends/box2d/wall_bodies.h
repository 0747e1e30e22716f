#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>

#include <array>

#include "fooball/scene.h"

namespace fooball::box2d_detail {

/// The walls that are on, as static Box2D bodies: one per side, a thick slab lying outside the box
/// cut into square pieces (one fixture each). Each wall's body holds its common::WallBit in its
/// user data (contact_counter.h).
/// Walls that are off do not exist, so Box2D does no work for them.
class WallBodies {
 public:
  /// Creates the walls `walls` turns on and destroys those it turns off, leaving the others (and
  /// their contacts) alone.
  void sync(b2World& world, const Box& box, const Walls& walls);

  /// Forgets the bodies without destroying them: their world is being destroyed.
  void forget() { bodies_ = {}; }

 private:
  std::array<b2Body*, 4> bodies_{};  ///< left, right, bottom, top; nullptr when off
};

}  // namespace fooball::box2d_detail
