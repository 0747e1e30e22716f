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
/// space is, at load or when the option changes; setBall does not resize it. Measured on the
/// standard gas beside the BB-tree in one `fooball-cli capacity` run (docs/performance.md): the
/// tree carries 1.2–1.3× the balls at one substep and 1.35–1.7× at four, so it stays the default.
struct HashSizing {
  double cell = 0.0;  ///< m, the side of a cell
  int cells = 0;      ///< buckets in the table
};

HashSizing hashSizing(std::span<const double> radii, const Box& box);

/// Switches the space (still empty, or not) to the spatial hash `sizing`.
void useSpatialHash(cpSpace* space, const HashSizing& sizing);

/// m: how far from the origin a ball may be while the spatial hash indexes it. The hash turns a
/// coordinate into a cell number with an int cast (cpSpaceHash.c, floor_int), which overflows
/// past 2^31 cells: at x < −2^31 cells floor_int returns INT_MAX, and the loop over the cells of
/// the ball's box (for i = l … r) never ends — a ball that leaves through a wall that is off
/// and keeps falling under strong gravity got there in the random invariants (seconds, at 1e-4 m
/// cells). Half of that range, 2^30 cells, leaves room for the ball's own extent; beyond it the
/// adapter moves the space to the BB-tree, which has no such limit (chipmunk_stepping.cpp).
inline double hashSafeCoordinate(double cell) {
  return 0x1p30 * cell;
}

}  // namespace fooball::chipmunk_detail
