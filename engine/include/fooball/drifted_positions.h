#pragma once

#include <vector>

#include "fooball/simulation.h"
#include "fooball/vec2.h"

namespace fooball {

/// Where `run`'s balls are `ahead` seconds (s, simulated) after its last step in free flight,
/// p + v·τ + ½ g τ², written to `out` (resized to the ball count): what a view draws between
/// steps, so that slow motion moves every frame (RunGroup::pendingTime gives τ). The physics is
/// untouched; this is for drawing only.
///
/// Extrapolated rather than interpolated between the last two steps: interpolation needs the
/// state before the last step kept for every run and lags the physics by up to a step (at
/// 0.05× that is a third of a second of real time, felt when dragging a ball), and shows the
/// step before the current one when paused. Extrapolation needs only the current state, has no
/// lag, and is the stepped state exactly at τ = 0 (paused, single-stepping). Its error is that
/// of one step of free flight: it ignores collisions and tool forces for at most one step
/// (overlap up to v·τ before a hit is stepped), and drag, whose effect over τ is c·τ times that
/// of the motion drawn. No centre is drawn beyond a wall that is on further than the stepped
/// state already has it: the drawn ball stops at the wall until the step that bounces it.
void driftedPositions(const Simulation& run, double ahead, std::vector<Vec2>& out);

}  // namespace fooball
