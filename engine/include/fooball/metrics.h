#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "fooball/backend.h"
#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball {

/// Energy, momentum and centre of mass of a state, computed the same way for every backend.
struct StateSums {
  double kineticEnergy = 0.0;    ///< J, Σ ½ m|v|²
  double potentialEnergy = 0.0;  ///< J, Σ −m (g·p), zero at y = 0
  Vec2 momentum;                 ///< N·s, Σ m v
  Vec2 centreOfMass;             ///< m
  double totalEnergy() const { return kineticEnergy + potentialEnergy; }
};

StateSums sumState(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                   std::span<const double> masses, Vec2 gravity);

/// Deepest ball–ball or ball–wall (walls that are on) penetration, as a fraction of the smaller
/// radius (for walls, of the ball's radius); 0 when nothing overlaps. O(N log N) with one
/// grid per power-of-two size, so mixed sizes cost no more than equal ones.
double maxOverlap(std::span<const Vec2> positions, std::span<const double> radii, const Box& box,
                  const Walls& walls);

/// Balls whose centre is outside the box.
std::size_t countEscaped(std::span<const Vec2> positions, const Box& box);

/// Whether a metrics sample runs the geometry checks (maxOverlap, countEscaped). They walk every
/// ball, O(N log N), and no chart plots them, so the app's chart samples skip them and only a
/// visible counters table pays for them.
enum class GeometryChecks { Run, Skip };

/// One row of `fooball-cli run --metrics` and of the app's charts.
struct Metrics {
  double time = 0.0;  ///< s, simulated
  StateSums sums;
  std::uint64_t ballCollisions = 0;
  std::uint64_t wallCollisions = 0;
  double wallImpulse = 0.0;  ///< N·s
  double maxOverlap = 0.0;   ///< fraction of the smaller radius; 0 with GeometryChecks::Skip
  std::size_t escaped = 0;   ///< 0 with GeometryChecks::Skip
  /// The energy budget (J): E(t) − E(0) − work by tools and edits + energy taken by drag.
  /// What is left is the method's own error.
  double externalWork = 0.0;
  double dragLoss = 0.0;
  double energyResidual = 0.0;
};

}  // namespace fooball
