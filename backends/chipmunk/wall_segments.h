#pragma once

#include <chipmunk/chipmunk.h>

#include <array>

#include "chipmunk_space.h"
#include "fooball/scene.h"

namespace fooball::chipmunk_detail {

/// The walls that are on, as static segment shapes on the space's static body, one per side.
/// Walls that are off do not exist, so Chipmunk does no work for them.
///
/// A Chipmunk segment is a capsule: an axis with a radius. Each wall's axis lies `thickness`
/// outside the box edge and its radius is `thickness`, so the surface balls bounce off is exactly
/// the box edge, and the contact normal (from the axis to the ball's centre) points into the box
/// for any centre on the box side of the axis, even one that a step carried past the edge. The
/// axes run `thickness` past the box corners, so a ball in the box never meets a rounded end.
/// Chipmunk has no continuous collision: a ball whose centre crosses the axis within one step
/// would be pushed out on the far side. The thickness sets how fast a ball can be before that
/// can happen (one step's travel beyond contact up to radius + thickness); beyond it the wall
/// containment (wall_containment.h) brings the ball back. It is the largest ball radius, and
/// no more than a cell of the spatial hash (broadphase.h): a thicker wall would cost the hash
/// cells for nothing the containment does not already guarantee.
class WallSegments {
 public:
  /// Creates the walls `walls` turns on and removes those it turns off, leaving the others (and
  /// their contacts) alone. `thickness` (m, > 0) applies to walls created now.
  void sync(Space& space, const Box& box, const Walls& walls, double thickness);

  /// Forgets the shapes without removing them: their space is being destroyed.
  void forget() { shapes_ = {}; }

 private:
  std::array<cpShape*, 4> shapes_{};  ///< left, right, bottom, top; nullptr when off
};

}  // namespace fooball::chipmunk_detail
