#pragma once

#include "ball_arrays.h"
#include "fooball/backend.h"
#include "fooball/cell_grid.h"

namespace fooball::elastic {

/// Resolves every overlapping pair found through `grid` (built on the balls' current centres,
/// cells at least one largest diameter wide), in cell order (Gauss–Seidel, deterministic):
/// - separates the pair along the line of centres, each ball moved in inverse proportion to its
///   mass so the centre of mass stays put, exactly to contact (no over-push);
/// - exchanges the elastic impulse J = 2μ·u_n (μ the reduced mass, u_n the closing speed) only
///   when the pair is approaching, so a pair that is already separating is not collided again;
/// - coincident centres get a deterministic normal instead of a division by zero.
void collidePairs(BallArrays& balls, const CellGrid& grid, BackendCounters& counters);

}  // namespace fooball::elastic
