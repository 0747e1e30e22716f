// Every preset's "what to look for" caption (engine/src/presets.cpp) holds at the app's defaults:
// the first registered backend with its default options, stepped at the app's frame step of
// 1/60 s. A caption that stops being true (a changed default, a changed preset) fails here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "fooball/metrics.h"
#include "fooball/presets.h"
#include "fooball/simulation.h"
#include "fooball/speed_distribution.h"
#include "registry.h"

namespace fooball {
namespace {

constexpr double kAppDt = 1.0 / 60.0;  // s: the app steps one frame of 60 Hz per step
/// Relative energy change allowed where the method conserves energy exactly but for rounding:
/// 1e-15 per operation over 10⁴–10⁶ collisions stays far below this.
constexpr double kRoundingOverARun = 1e-9;

/// The preset on the app's default backend (the registry's first) with its default options.
Simulation appDefault(std::string_view preset) {
  Simulation simulation(loadPreset(preset), createBackend(registeredBackends().front().name));
  EXPECT_EQ(simulation.dt(), kAppDt);
  return simulation;
}

void runFor(Simulation& simulation, double seconds) {
  const double end = simulation.time() + seconds - 0.5 * kAppDt;
  while (simulation.time() < end)
    simulation.step();
}

/// Steps until the first ball–ball collision; fails (and stops) when a wall bounce comes first
/// or nothing happens within `limit` s.
void stepToFirstCollision(Simulation& simulation, double limit) {
  while (simulation.counters().ballCollisions == 0 && simulation.time() < limit)
    simulation.step();
  EXPECT_EQ(simulation.counters().ballCollisions, 1u);
  EXPECT_EQ(simulation.counters().wallCollisions, 0u);
}

double totalEnergy(const Simulation& simulation) {
  return simulation.metrics(GeometryChecks::Skip).sums.totalEnergy();
}

TEST(PresetPromises, DefaultTradesKineticForPotentialEnergyAndKeepsTheirSum) {
  Simulation simulation = appDefault("default");
  const double initial = totalEnergy(simulation);
  double lowestKinetic = INFINITY;
  double highestKinetic = 0.0;
  for (int second = 0; second < 30; ++second) {
    runFor(simulation, 1.0);
    const Metrics metrics = simulation.metrics(GeometryChecks::Skip);
    lowestKinetic = std::min(lowestKinetic, metrics.sums.kineticEnergy);
    highestKinetic = std::max(highestKinetic, metrics.sums.kineticEnergy);
    EXPECT_NEAR(metrics.sums.totalEnergy(), initial, kRoundingOverARun * initial);
    EXPECT_NEAR(metrics.energyResidual, 0.0, kRoundingOverARun * initial);
  }
  // The trade is visible: the kinetic share swings by more than a tenth of the total.
  EXPECT_GT(highestKinetic - lowestKinetic, 0.1 * initial);
  EXPECT_GT(simulation.counters().ballCollisions, 1000u);
}

/// Balls slower than `low` and faster than `high` (m/s).
std::size_t speedsOutside(const Simulation& simulation, double low, double high) {
  return std::size_t(std::count_if(simulation.velocities().begin(), simulation.velocities().end(),
                                   [&](Vec2 v) { return length(v) < low || length(v) > high; }));
}

TEST(PresetPromises, GasRelaxesToMaxwellBoltzmannGrowingTailsNoBallStartedIn) {
  Simulation simulation = appDefault("gas");
  // The scene's speed range (gas.json: random_balls.speed): no ball starts outside it.
  constexpr double kSlowest = 0.5;  // m/s
  constexpr double kFastest = 4.0;  // m/s
  EXPECT_EQ(speedsOutside(simulation, kSlowest, kFastest), 0u);
  const std::size_t balls = simulation.ballCount();
  const MaxwellBoltzmann2D equilibrium(
      simulation.masses(), kineticTemperature(simulation.masses(), simulation.velocities()));
  const double expectedOutside =
      double(balls) - equilibrium.expectedCount(kSlowest, kFastest, balls);
  const double initial = totalEnergy(simulation);
  runFor(simulation, 10.0);
  // Ten snapshots a second apart. The Kolmogorov–Smirnov test's 5% critical distance for this
  // many speeds is 1.36/√N; at equilibrium the expected distance is about 0.87/√N, so the mean
  // over the snapshots stays below the critical one (a single one may stray beyond it).
  double distance = 0.0;
  double outside = 0.0;
  constexpr int kSnapshots = 10;
  std::vector<double> scratch;
  for (int k = 0; k < kSnapshots; ++k) {
    runFor(simulation, 1.0);
    const double kT = kineticTemperature(simulation.masses(), simulation.velocities());
    distance += maxwellBoltzmannDistance(simulation.masses(), simulation.velocities(), kT, scratch);
    outside += double(speedsOutside(simulation, kSlowest, kFastest));
  }
  EXPECT_LT(distance / kSnapshots, 1.36 / std::sqrt(double(balls)));
  // The tails no ball started in fill as Maxwell–Boltzmann says (about 10% of the balls): half
  // the expected count is several standard deviations of the snapshots' mean below it.
  EXPECT_GT(outside / kSnapshots, 0.5 * expectedOutside);
  EXPECT_NEAR(totalEnergy(simulation), initial, kRoundingOverARun * initial);
}

TEST(PresetPromises, HeadOnBallsSwapVelocities) {
  Simulation simulation = appDefault("head-on");
  const Vec2 before0 = simulation.velocities()[0];
  const Vec2 before1 = simulation.velocities()[1];
  stepToFirstCollision(simulation, 5.0);
  const double speed = length(before0);
  EXPECT_LT(length(simulation.velocities()[0] - before1), kRoundingOverARun * speed);
  EXPECT_LT(length(simulation.velocities()[1] - before0), kRoundingOverARun * speed);
}

TEST(PresetPromises, GlancingBallsLeaveAtRightAngles) {
  Simulation simulation = appDefault("glancing");
  const Vec2 incoming = simulation.velocities()[0];
  stepToFirstCollision(simulation, 5.0);
  const Vec2 striker = simulation.velocities()[0];
  const Vec2 target = simulation.velocities()[1];
  // Right angles: the cosine between them is 0 up to rounding.
  EXPECT_NEAR(dot(striker, target) / lengthSquared(incoming), 0.0, kRoundingOverARun);
  // A real glancing hit: both leave with a good part of the speed (not a miss, not head-on).
  EXPECT_GT(length(striker), 0.1 * length(incoming));
  EXPECT_GT(length(target), 0.1 * length(incoming));
}

TEST(PresetPromises, CradlePassesTheMomentumToTheLastBallAlone) {
  Simulation simulation = appDefault("cradle");
  const Vec2 strike = simulation.velocities()[0];
  const std::size_t last = simulation.ballCount() - 1;
  // The striker meets the row at 1 s; the last ball would reach the right wall at 1.875 s.
  runFor(simulation, 1.5);
  EXPECT_EQ(simulation.counters().wallCollisions, 0u);
  EXPECT_EQ(simulation.counters().ballCollisions, last);  // one hit per pair along the row
  EXPECT_LT(length(simulation.velocities()[last] - strike), kRoundingOverARun * length(strike));
  for (std::size_t i = 0; i < last; ++i)
    EXPECT_LT(length(simulation.velocities()[i]), kRoundingOverARun * length(strike))
        << "ball " << i;
}

TEST(PresetPromises, BilliardsBreakSetsAllSixteenMovingWithinTwentySeconds) {
  Simulation simulation = appDefault("billiards");
  const double cueSpeed = length(simulation.velocities()[0]);
  const double initial = totalEnergy(simulation);
  // Each ball's top speed so far: the gas is chaotic, so any one ball may be slow at any one
  // moment; the promise is that each gets hit and set moving.
  std::vector<double> fastest(simulation.ballCount(), 0.0);
  while (simulation.time() < 20.0 - 0.5 * kAppDt) {
    simulation.step();
    for (std::size_t i = 0; i < simulation.ballCount(); ++i)
      fastest[i] = std::max(fastest[i], length(simulation.velocities()[i]));
  }
  // Moving, not creeping: 5% of the cue's speed crosses the box in under 30 s.
  for (std::size_t i = 0; i < simulation.ballCount(); ++i)
    EXPECT_GT(fastest[i], 0.05 * cueSpeed) << "ball " << i;
  EXPECT_NEAR(totalEnergy(simulation), initial, kRoundingOverARun * initial);
}

TEST(PresetPromises, MassRatioCountsThirtyOneCollisionsOneFrameApartAtLeast) {
  Simulation simulation = appDefault("mass-ratio");
  std::uint64_t shown = 0;
  double first = 0.0;
  double last = 0.0;
  while (simulation.time() < 60.0) {
    simulation.step();
    const BackendCounters counters = simulation.counters();
    const std::uint64_t hits = counters.ballCollisions + counters.wallCollisions;
    // Watchable: the counter shown once a frame goes up one at a time, never skipping a number.
    EXPECT_LE(hits - shown, 1u) << "at t = " << simulation.time() << " s";
    if (hits > shown && shown == 0) first = simulation.time();
    if (hits > shown) last = simulation.time();
    shown = hits;
  }
  EXPECT_EQ(simulation.counters().ballCollisions, 16u);
  EXPECT_EQ(simulation.counters().wallCollisions, 15u);
  EXPECT_LT(first, 2.0);          // s: the show starts at once
  EXPECT_GT(last - first, 10.0);  // s: and lasts long enough to follow
}

/// How the tunnelling preset's shooter (ball 0) meets the barrier: it passes when it gets beyond
/// the barrier's far side still moving right; it bounces when it turns back first.
enum class Outcome { Passes, Bounces };
Outcome shoot(Simulation& simulation) {
  const double barrier = simulation.positions()[1].x + simulation.radii()[1];
  while (simulation.time() < 1.0) {
    simulation.step();
    const Vec2 position = simulation.positions()[0];
    if (simulation.velocities()[0].x < 0.0) return Outcome::Bounces;
    if (position.x - simulation.radii()[0] > barrier) return Outcome::Passes;
  }
  ADD_FAILURE() << "the shooter neither passed nor bounced within 1 s";
  return Outcome::Bounces;
}

TEST(PresetPromises, TunnellingShooterPassesThroughTheGapAtTheDefaultsAndBouncesAtSixteen) {
  Simulation simulation = appDefault("tunnelling");
  const Vec2 velocity = simulation.velocities()[0];
  EXPECT_EQ(shoot(simulation), Outcome::Passes);
  EXPECT_EQ(simulation.counters().ballCollisions, 0u);  // no substep ever saw it touch
  EXPECT_EQ(simulation.velocities()[0], velocity);

  // The caption's cure: 16 substeps move it 0.156 m per substep, less than the 0.25 m before
  // the gap's centre where a contact throws it back.
  Simulation finer = appDefault("tunnelling");
  ASSERT_TRUE(finer.backend().options().has("substeps"));
  finer.backend().setOption("substeps", 16);
  EXPECT_EQ(shoot(finer), Outcome::Bounces);
}

TEST(PresetPromises, DenseCollidesOverTenThousandTimesASecondWithSmallOverlaps) {
  Simulation simulation = appDefault("dense");
  const double initial = totalEnergy(simulation);
  constexpr double kSeconds = 10.0;
  double deepest = 0.0;
  for (int second = 0; second < int(kSeconds); ++second) {
    runFor(simulation, 1.0);
    deepest = std::max(deepest, simulation.metrics().maxOverlap);
  }
  EXPECT_GT(double(simulation.counters().ballCollisions) / kSeconds, 10'000.0);
  // The overlap column has something to show, and it stays a small fraction of a radius (the
  // 0.1 r the failure map counts as failing).
  EXPECT_GT(deepest, 0.0);
  EXPECT_LT(deepest, 0.1);
  EXPECT_NEAR(totalEnergy(simulation), initial, kRoundingOverARun * initial);
}

TEST(PresetPromises, RainSettlesIntoAPileWithinTwentyFiveSeconds) {
  Simulation simulation = appDefault("rain");
  const double initial = totalEnergy(simulation);
  // The energy of every ball hopping by one radius: a pile whose kinetic energy is a tenth of it
  // is at rest to the eye.
  double hop = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i)
    hop += simulation.masses()[i] * length(simulation.world().gravity) * simulation.radii()[i];
  runFor(simulation, 15.0);
  const double residualAt15 = simulation.metrics(GeometryChecks::Skip).energyResidual;
  runFor(simulation, 10.0);
  const Metrics settled = simulation.metrics(GeometryChecks::Skip);
  EXPECT_LT(settled.sums.kineticEnergy, 0.1 * hop);
  // Every ball in the pile on the floor: 624 balls of r = 0.1 m fill eight rows of the 16 m
  // floor when packed, 1.4 m; none is still up in the air.
  for (std::size_t i = 0; i < simulation.ballCount(); ++i)
    EXPECT_LT(simulation.positions()[i].y, 2.0) << "ball " << i;
  // The creep the residual chart shows: energy the method adds at resting contacts (which drag
  // takes out again), small beside the energy the rain started with.
  EXPECT_GT(settled.energyResidual, residualAt15);
  EXPECT_LT(settled.energyResidual, 0.01 * initial);
}

}  // namespace
}  // namespace fooball
