#pragma once

#include <box2d/b2_body.h>

#include <cstdint>
#include <span>

#include "fooball/vec2.h"
#include "wall_containment.h"

namespace fooball::box2d_detail {

/// What one pass over the balls' velocities between two Box2D steps tells the step loop: the
/// fastest speed (auto_substeps), the sums the drag accounting needs, and the cap hits of the
/// step just taken.
struct VelocityScan {
  double fastestSpeed = 0.0;      ///< m/s
  double massSpeedSquared = 0.0;  ///< kg·m²/s², Σ m|v|² (twice the kinetic energy)
  Vec2 momentum;                  ///< N·s, Σ m v
  std::uint64_t ballsAtCap = 0;   ///< balls at or above `capSpeed`
};

/// Whether a scan also sums Σ m|v|² and Σ m v. Only the drag accounting reads them; without drag,
/// leaving them out takes the scan after every Box2D step from 26 to 16 instructions a ball.
enum class MassSums { kSkip, kCompute };

/// `masses` (kg) are the scene's, in the order of `balls`; `capSpeed` in m/s (infinity: count
/// none). With MassSums::kSkip the sums stay 0. With `walls`, each ball is first put back if
/// Box2D left it beyond a wall, and scanned with the velocity it then has.
VelocityScan scanVelocities(std::span<b2Body* const> balls, std::span<const double> masses,
                            double capSpeed, MassSums sums, WallContainment* walls = nullptr);

}  // namespace fooball::box2d_detail
