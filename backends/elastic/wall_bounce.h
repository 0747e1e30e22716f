#pragma once

#include "ball_arrays.h"
#include "fooball/backend.h"
#include "fooball/scene.h"

namespace fooball::elastic {

/// Reflects every ball that has crossed a wall that is on, counting bounces and the impulse the
/// walls deliver. The position is mirrored back into the box (exact for straight flight), and
/// the outgoing normal speed is chosen so the mirror does not change the energy under gravity:
/// ½v'² = ½v² + (g·n)·2δ, where δ is the penetration. A plain mirror would gain m·g·2δ on every
/// floor bounce, and a ball would bounce ever higher.
void bounceOffWalls(BallArrays& balls, const Box& box, const Walls& walls, Vec2 gravity,
                    BackendCounters& counters);

}  // namespace fooball::elastic
