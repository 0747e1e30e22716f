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
  double wallImpulse = 0.0;        ///< N·s
  double maxOverlap = 0.0;         ///< fraction of the smaller radius; 0 with GeometryChecks::Skip
  std::size_t escaped = 0;         ///< 0 with GeometryChecks::Skip
  std::uint64_t restingBalls = 0;  ///< BackendCounters::restingBalls, now
  /// The energy budget (J): E(t) − E(0) − work by tools and edits + energy taken by drag −
  /// energy changed by a resting rule. What is left is the method's own error.
  double externalWork = 0.0;
  double dragLoss = 0.0;
  double restEnergyChange = 0.0;  ///< J, BackendCounters::restEnergyChange
  double energyResidual = 0.0;
  /// J, E(0): the run's total energy where its budget began (load, restart), which the
  /// residual is measured from and relativeEnergyError divides by.
  double initialEnergy = 0.0;
};

/// The relative energy error, the one definition every chart, table, warning and tool uses
/// (docs/accuracy.md, "The relative energy error"): the energy budget's residual (J) over
/// |E(0)|, the run's own total energy where its budget began, e.g. −0.01 for a method that lost
/// 1% of the energy the run started with.
///
/// Why |E(0)|: it stays fixed over the run, so the number moves only when the method's error
/// does (a divisor that followed E(t) would shrink the error of a method that pumps energy in:
/// tripled energy would read 0.67, not 2), and the runs of a group start from one state, so they
/// share it. For the usual scenes (gravity down or none, balls in the box) it equals
/// KE(0) + |PE(0)|. Under gravity it includes the potential energy above y = 0, so a resting
/// pile's number is small beside a scale of its own (the failure map's pile sweep divides by
/// Σ m·g·r instead: a different quantity with its own name there).
///
/// Zero and near zero: NaN when E(0) is 0 (balls at rest without gravity; nothing to be relative
/// to), which charts leave as a gap, tables print as such and the limit check does not flag;
/// the residual in joules still says what happened. Near zero there is no floor: the energy of a
/// scene spans orders of magnitude with its size (the failure map's scale sweep runs from 1e-4 to
/// 1e4 m, 1e-16 to 1e16 J), so any floor in joules would be wrong at one end; a small E(0) gives
/// an honest large ratio.
double relativeEnergyError(double energyResidual, double initialEnergy);
inline double relativeEnergyError(const Metrics& metrics) {
  return relativeEnergyError(metrics.energyResidual, metrics.initialEnergy);
}

}  // namespace fooball
