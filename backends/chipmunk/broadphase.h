#pragma once

#include <chipmunk/chipmunk.h>

#include <span>

#include "fooball/scene.h"

namespace fooball::chipmunk_detail {

/// A spatial hash sized from the balls, instead of the bounding-box tree every new space has
/// (cpSpaceNew). Chipmunk's advice (cpSpace.h): cells about the size of a typical shape, and
/// about 10× as many cells as shapes. So a cell is the mean ball diameter, but at least 1/4096 of
/// the box's longer side, so a wall covers a bounded number of cells whatever the radii (the
/// random invariants put balls of 1e-5 of the box beside balls 100× larger); the table has 10
/// cells per ball (at least 1'000; at most 2^24, far below the 1.6e9 at which cpSpaceHashResize
/// aborts). Without balls a cell is a tenth of the box's shorter side. A hash is built when the
/// space is, at load or when the option changes; setBall does not resize it.
struct HashSizing {
  double cell = 0.0;  ///< m, the side of a cell
  int cells = 0;      ///< buckets in the table
};

HashSizing hashSizing(std::span<const double> radii, const Box& box);

/// Switches the space (still empty, or not) to the spatial hash `sizing`.
void useSpatialHash(cpSpace* space, const HashSizing& sizing);

}  // namespace fooball::chipmunk_detail
