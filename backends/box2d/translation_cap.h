#pragma once

#include <box2d/b2_common.h>

namespace fooball::box2d_detail {

/// m. b2_maxTranslation: after the velocity solve, Box2D scales down any velocity that would
/// move a body farther than this in one Box2D step (b2Island::Solve and SolveTOI), silently
/// taking kinetic energy away. It is a compile-time constant, so the only cure is a shorter
/// Box2D step: a cap on speed of b2_maxTranslation / h.
inline constexpr double kMaxTranslation = static_cast<double>(b2_maxTranslation);

/// The fraction of the cap auto_substeps plans for. Collisions inside a Box2D step can speed a
/// ball up before Box2D checks the cap: a light ball struck head-on by a much heavier one leaves
/// at up to 3× the faster speed (v' = 2V − v). Planning for a quarter of the cap keeps that under
/// it; the check before every Box2D step replans for what collisions did in earlier ones.
inline constexpr double kPlannedFractionOfCap = 0.25;

/// The most Box2D steps auto_substeps gives one step() (the substeps option's maximum), so an
/// absurd speed costs bounded time; the cap hits it cannot avoid are reported.
inline constexpr int kMaxBox2dStepsPerStep = 1000;

/// Relative margin below the cap speed at which a ball counts as at the cap. The clamp leaves
/// |v|·h = b2_maxTranslation to float rounding (~1e-7); a ball this close is at the cap anyway.
inline constexpr double kCapSpeedTolerance = 1e-5;

/// The fewest equal Box2D steps covering `duration` (s) in which no ball moves more than the
/// planned fraction of the cap, given the fastest speed (m/s) now and |g| (m/s²), which can add
/// at most |g|·duration. Clamped to [1, maxSteps].
int box2dStepsBelowCap(double fastestSpeed, double gravity, double duration, int maxSteps);

/// m/s: the speed at which a ball counts as at the cap after a Box2D step of `box2dStep` s.
inline double capSpeed(double box2dStep) {
  return (1.0 - kCapSpeedTolerance) * kMaxTranslation / box2dStep;
}

}  // namespace fooball::box2d_detail
