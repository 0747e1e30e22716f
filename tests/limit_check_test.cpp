// The method-limits check: from a run's state and settings, the failure map's numbers
// (docs/accuracy.md), held against the boundaries each backend states beside its registry line.
// A run within every measured range crosses nothing; strong gravity on a pile, a fast shooter and
// a large energy error are each named.

#include "fooball/limit_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "fooball/presets.h"
#include "fooball/run_spec.h"
#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;

Simulation simulationOf(const Scene& scene, const std::string& spec) {
  return Simulation(scene, createBackend(parseRunSpec(spec)));
}

std::vector<CrossedLimit> crossedOn(const Simulation& run, const std::string& spec) {
  return crossedLimits(run, backendInfo(parseRunSpec(spec).backend).limits);
}

bool crosses(const std::vector<CrossedLimit>& crossed, MethodLimit limit) {
  return std::any_of(crossed.begin(), crossed.end(),
                     [&](const CrossedLimit& c) { return c.limit == limit; });
}

/// The default preset under 300 m/s² with air resistance: the balls settle into a pile.
Scene heavyDefaultScene() {
  Scene scene = loadPreset(kDefaultPreset);
  scene.world.gravity = {0.0, -300.0};
  scene.world.airResistance = 0.5;
  return scene;
}

/// The map's tunnelling scene: a 0.05 m ball shot at 30 m/s at a resting twin. At dt = 1/60 s
/// and 4 substeps that is v·h/r = 30 / 240 / 0.05 = 2.5 radii per substep.
Scene fastShooter() {
  Scene scene = emptyBox();
  scene.balls = {ball({3.0, 4.5}, {30.0, 0.0}, 0.05), ball({10.0, 4.5}, {0.0, 0.0}, 0.05)};
  return scene;
}

TEST(LimitCheck, TheDefaultSceneAtDefaultSettingsCrossesNoLimit) {
  for (const std::string spec : {"elastic", "exact"}) {
    Simulation run = simulationOf(loadPreset(kDefaultPreset), spec);
    EXPECT_TRUE(crossedOn(run, spec).empty()) << spec << " at t = 0";
    run.run(5.0);
    const auto crossed = crossedOn(run, spec);
    EXPECT_TRUE(crossed.empty()) << spec << ": " << methodLimitNotice(crossed);
  }
}

TEST(LimitCheck, StrongGravityOnElasticCrossesTheRestingPileLimit) {
  Simulation run = simulationOf(heavyDefaultScene(), "elastic");
  run.run(5.0);
  const LimitNumbers numbers = measureLimitNumbers(run);
  // The smallest ball of the default scene is 0.2 m: g·h²/r = 300 / 240² / 0.2 = 0.026, beyond
  // elastic's first measured failure, 100 m/s² on 0.1 m balls (0.017).
  EXPECT_NEAR(numbers.pileSinkPerSolverStep, 300.0 / (240.0 * 240.0) / 0.2, 6e-4);
  const auto crossed = crossedOn(run, "elastic");
  ASSERT_TRUE(crosses(crossed, MethodLimit::RestingPile)) << methodLimitNotice(crossed);
  EXPECT_EQ(limitName(MethodLimit::RestingPile), "resting pile");
  EXPECT_NE(methodLimitNotice(crossed).find("resting pile (g·h²/r = "), std::string::npos)
      << methodLimitNotice(crossed);
  EXPECT_FALSE(crosses(crossed, MethodLimit::Tunnelling));
  // More substeps lower the number with their square: 16 substeps bring it under the limit.
  const Simulation finer = simulationOf(heavyDefaultScene(), "elastic:substeps=16");
  EXPECT_FALSE(crosses(crossedOn(finer, "elastic:substeps=16"), MethodLimit::RestingPile));
}

TEST(LimitCheck, TheExactSolverClaimsNoPileLimit) {
  // Its pile fails only in steps cut short at an event cap, which the cut-short notice reports;
  // its energy stays exact. (Not stepped: without a cap such a step never ends.)
  const Simulation run = simulationOf(heavyDefaultScene(), "exact");
  EXPECT_GT(measureLimitNumbers(run).pileSinkPerSolverStep, 0.0);
  EXPECT_TRUE(crossedOn(run, "exact").empty());
}

TEST(LimitCheck, NoPileWithoutBallCollisionsOrAWallToRestOn) {
  Scene scene = heavyDefaultScene();
  scene.world.ballCollisions = false;
  EXPECT_EQ(measureLimitNumbers(simulationOf(scene, "elastic")).pileSinkPerSolverStep, 0.0);
  scene.world.ballCollisions = true;
  scene.world.walls.bottom = false;
  EXPECT_EQ(measureLimitNumbers(simulationOf(scene, "elastic")).pileSinkPerSolverStep, 0.0);
}

TEST(LimitCheck, AFastShooterCrossesTheTunnellingLimitOnElasticNotOnExact) {
  const Simulation elastic = simulationOf(fastShooter(), "elastic");
  EXPECT_DOUBLE_EQ(measureLimitNumbers(elastic).closingPerSolverStep, 30.0 / 240.0 / 0.05);
  const auto crossed = crossedOn(elastic, "elastic");
  ASSERT_EQ(crossed.size(), 1u) << methodLimitNotice(crossed);
  EXPECT_EQ(crossed[0].limit, MethodLimit::Tunnelling);
  EXPECT_EQ(crossed[0].boundary, 2.38);
  EXPECT_EQ(crossed[0].passesUpTo, 2.0);
  EXPECT_NE(limitExplanation(crossed[0]).find("measured to hold up to 2 and to fail from 2.38"),
            std::string::npos)
      << limitExplanation(crossed[0]);
  EXPECT_TRUE(crossedOn(simulationOf(fastShooter(), "exact"), "exact").empty());
  // Twice the substeps halve the number: 1.25 radii per substep is within the limit.
  EXPECT_TRUE(
      crossedOn(simulationOf(fastShooter(), "elastic:substeps=8"), "elastic:substeps=8").empty());
}

TEST(LimitCheck, ALargeEnergyErrorIsNamedWhateverTheCause) {
  LimitNumbers numbers;
  numbers.relativeEnergyError = -0.09;
  EXPECT_TRUE(crossedLimits(numbers, MethodLimits{}).empty()) << "9% is within 10%";
  numbers.relativeEnergyError = -0.12;
  const auto crossed = crossedLimits(numbers, MethodLimits{});
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].limit, MethodLimit::EnergyError);
  EXPECT_DOUBLE_EQ(crossed[0].value, 0.12);
  numbers.relativeEnergyError = 0.12;
  EXPECT_EQ(crossedLimits(numbers, MethodLimits{}).size(), 1u) << "a gain counts as a loss";
  numbers.relativeEnergyError = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(crossedLimits(numbers, MethodLimits{}).empty()) << "no E(0), no share of it";
}

TEST(LimitCheck, PackingIsTheCoveredShareOfTheBox) {
  Scene scene = emptyBox(4.0, 2.0);
  scene.balls = {ball({1.0, 1.0}, {0.0, 0.0}, 0.5), ball({3.0, 1.0}, {0.0, 0.0}, 0.5)};
  const Simulation run = simulationOf(scene, "elastic");
  EXPECT_DOUBLE_EQ(measureLimitNumbers(run).packingFraction, 2.0 * std::numbers::pi * 0.25 / 8.0);
  MethodLimits limits;
  limits.packing = MeasuredBoundary{0.0, 0.15};  // the lowest packing tried failed
  const auto crossed = crossedLimits(run, limits);
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].limit, MethodLimit::Packing);
  EXPECT_EQ(crossed[0].boundary, 0.15);
}

}  // namespace
}  // namespace fooball
