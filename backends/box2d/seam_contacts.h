#pragma once

#include <box2d/b2_contact.h>

namespace fooball::box2d_detail {

/// Disables, for this Box2D step, a ball's contact with a corner of a wall piece.
///
/// Each wall is a row of square pieces (wall_bodies.h). Where two pieces meet, a ball that
/// overlaps the wall also touches the corner of the next piece, and Box2D collides it with that
/// corner along a normal tilted towards the ball's motion: a "ghost" collision that kicks a ball
/// sliding along the wall off it (a 1 mm overlap gave 0.24 m/s at 3 m/s). The faces of the
/// pieces are contiguous, so the face of one piece always holds the ball there; only the corner
/// contact is dropped. Face contacts have axis-aligned normals (the pieces are axis-aligned
/// boxes); a contact whose normal is not axis-aligned is a corner. The only other corners are the
/// slabs' far ends, outside the box, where a ball that hits one is held by the faces instead.
void disableWallCornerContact(b2Contact& contact);

}  // namespace fooball::box2d_detail
