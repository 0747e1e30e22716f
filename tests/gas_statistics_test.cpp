#include "fooball/gas_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "backend_factory.h"
#include "fooball/run_group.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::gas;
using testing::makeBackend;

std::size_t total(const std::vector<std::size_t>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0});
}

TEST(GasStatistics, EveryRunsHistogramCountsEveryBallOverTheSameBins) {
  RunGroup group(gas(300), {RunSpec{"elastic", {}}, RunSpec{"exact", {}}}, &makeBackend);
  group.runFor(1.0);
  GasMonitor monitor;
  const double range = 2.0;  // m/s: too short on purpose, so some balls are above it
  const GasMonitor::Snapshot& snapshot = monitor.measure(group, speedBins(300), range);
  ASSERT_EQ(snapshot.runs.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const RunGasStatistics& run = snapshot.runs[i];
    EXPECT_EQ(run.balls, 300u);
    EXPECT_EQ(run.histogram.counts.size(), speedBins(300));
    EXPECT_DOUBLE_EQ(run.histogram.range(), range);
    EXPECT_GT(run.histogram.above, 0u);
    EXPECT_EQ(total(run.histogram.counts) + run.histogram.above, 300u) << "run " << i;
    // The very histogram speed_distribution.h makes of the run's velocities.
    EXPECT_EQ(run.histogram.counts,
              speedHistogram(group.run(i).velocities(), speedBins(300), range).counts);
    EXPECT_DOUBLE_EQ(run.kineticTemperature,
                     kineticTemperature(group.run(i).masses(), group.run(i).velocities()));
  }
}

TEST(GasStatistics, MaxwellBoltzmannCountsAddUpToTheBallsOverTheRangeShown) {
  // Mixed masses (radius 0.1–0.2 m): the lightest ball's thermal width sets the range.
  RunGroup group(gas(400), {RunSpec{"elastic", {}}}, &makeBackend);
  GasMonitor monitor;
  // Far beyond every ball's speeds: the curve's counts integrate the whole distribution.
  const double wide = 40.0 * speedToShow(group.run(0));
  const auto sum = [](const std::vector<double>& counts) {
    return std::accumulate(counts.begin(), counts.end(), 0.0);
  };
  EXPECT_NEAR(sum(monitor.measure(group, speedBins(400), wide).expectedCounts), 400.0, 1e-9);
  // Over the range speedToShow() gives at equilibrium (kTailWidths of the lightest ball), all
  // but e⁻¹⁸ of it.
  const RunGasStatistics& run = monitor.latest().runs.front();
  const double lightest =
      *std::min_element(group.run(0).masses().begin(), group.run(0).masses().end());
  const double shown = kTailWidths * std::sqrt(run.kineticTemperature / lightest);
  const std::vector<double> counts = monitor.measure(group, speedBins(400), shown).expectedCounts;
  EXPECT_EQ(counts.size(), speedBins(400));
  EXPECT_NEAR(sum(counts), 400.0, 400.0 * 1e-7);
  EXPECT_LT(sum(counts), 400.0);
}

TEST(GasStatistics, TheRangeShownHoldsTheFastestBallButNotAFlungOne) {
  Scene scene = gas(300);
  RunGroup calm(scene, {RunSpec{"elastic", {}}}, &makeBackend);
  double fastest = 0.0;
  for (const Vec2 v : calm.run(0).velocities())
    fastest = std::max(fastest, length(v));
  EXPECT_DOUBLE_EQ(speedToShow(calm.run(0)), fastest);

  scene.balls.front().velocity = {1000.0, 0.0};  // m/s, the slingshot's work
  RunGroup flung(scene, {RunSpec{"elastic", {}}}, &makeBackend);
  const Simulation& run = flung.run(0);
  const double lightest = *std::min_element(run.masses().begin(), run.masses().end());
  const double width = std::sqrt(kineticTemperature(run.masses(), run.velocities()) / lightest);
  EXPECT_DOUBLE_EQ(speedToShow(run), kTailWidths * width);
  EXPECT_LT(speedToShow(run), 1000.0);

  EXPECT_EQ(
      speedToShow(RunGroup(testing::emptyBox(), {RunSpec{"elastic", {}}}, &makeBackend).run(0)),
      0.0);
}

TEST(GasStatistics, BinsFollowRicesRuleWithinBounds) {
  EXPECT_EQ(speedBins(300), 13u);     // 2·300^⅓ = 13.4
  EXPECT_EQ(speedBins(10'000), 43u);  // 2·10000^⅓ = 43.1
  EXPECT_EQ(speedBins(1), 10u);
  EXPECT_EQ(speedBins(1'000'000), 60u);
}

TEST(GasStatistics, PressureAndRateAverageOverTheWindowAndStartAgainOnRestart) {
  RunGroup group(gas(300), {RunSpec{"elastic", {}}}, &makeBackend);
  GasMonitor monitor(2.0);
  const BackendCounters before = group.run(0).counters();
  monitor.measure(group, 20, 5.0);
  EXPECT_EQ(monitor.latest().runs.front().windowSpan, 0.0);
  EXPECT_EQ(monitor.latest().runs.front().wallPressure, 0.0);
  group.runFor(1.5);
  const RunGasStatistics& run = monitor.measure(group, 20, 5.0).runs.front();
  const BackendCounters after = group.run(0).counters();
  EXPECT_NEAR(run.windowSpan, 1.5, 1e-9);
  // Impulse per second per metre of the box's 50 m of walls; two balls per collision.
  EXPECT_DOUBLE_EQ(run.wallPressure,
                   (after.wallImpulse - before.wallImpulse) / (run.windowSpan * 50.0));
  EXPECT_DOUBLE_EQ(run.collisionRate, 2.0 * double(after.ballCollisions - before.ballCollisions) /
                                          (300.0 * run.windowSpan));
  EXPECT_GT(run.collisionRate, 0.0);

  group.runFor(3.0);  // the window slides: the oldest measurement falls out
  monitor.measure(group, 20, 5.0);
  EXPECT_NEAR(monitor.latest().runs.front().windowSpan, 3.0, 1e-9);

  group.restart();  // time and counters from 0: the window starts again
  EXPECT_EQ(monitor.measure(group, 20, 5.0).runs.front().windowSpan, 0.0);
}

TEST(GasStatistics, CaveatsNameWhatKeepsTheGasFromEquilibrium) {
  WorldSettings world;
  Interactions interactions;
  EXPECT_FALSE(theoryCaveats(world, interactions).any());
  world.gravity = {0.0, -9.81};
  EXPECT_TRUE(theoryCaveats(world, interactions).gravity);
  world = {};
  world.airResistance = 0.1;
  EXPECT_TRUE(theoryCaveats(world, interactions).drag);
  world = {};
  world.ballCollisions = false;
  EXPECT_TRUE(theoryCaveats(world, interactions).noBallCollisions);
  world = {};
  world.walls.top = false;
  EXPECT_TRUE(theoryCaveats(world, interactions).openWalls);
  world = {};
  interactions.addAttractor({8.0, 4.5});
  EXPECT_TRUE(theoryCaveats(world, interactions).attractors);
  EXPECT_TRUE(theoryCaveats(world, interactions).any());
}

}  // namespace
}  // namespace fooball
