// Rewind (fooball/run_history.h): a run group rewound to a kept moment and stepped forward gives
// the states, counters, clock and energy budget it had, bit for bit, on every backend; the
// moments stay within their byte bound; continuing after a rewind drops the future.

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "backend_factory.h"
#include "fooball/run_group.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::makeBackend;

/// 3 big balls and 200 small ones falling under gravity in a 16 × 9 m box: ball and wall
/// collisions every step, and cells holding many balls (where elastic's storage order, which it
/// re-sorts now and then, orders its sums: a saved state alone does not resume it bit for bit).
Scene fallingGas() {
  Scene scene = testing::bigAmongSmall(3, 200, 16.0, 9.0);
  scene.world.gravity = {0.0, -9.81};
  return scene;
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Everything of a simulation that rewinding must give back, compared bit for bit.
struct Snapshot {
  std::vector<Vec2> positions;
  std::vector<Vec2> velocities;
  BackendCounters counters;
  double time = 0.0;
  std::uint64_t steps = 0;
  double energyResidual = 0.0;

  explicit Snapshot(const Simulation& simulation)
      : positions(simulation.positions().begin(), simulation.positions().end()),
        velocities(simulation.velocities().begin(), simulation.velocities().end()),
        counters(simulation.counters()),
        time(simulation.time()),
        steps(simulation.steps()),
        energyResidual(simulation.metrics(GeometryChecks::Skip).energyResidual) {}

  bool operator==(const Snapshot& other) const {
    const auto sameVectors = [](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
      return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)) == 0;
    };
    return sameVectors(positions, other.positions) && sameVectors(velocities, other.velocities) &&
           counters.ballCollisions == other.counters.ballCollisions &&
           counters.wallCollisions == other.counters.wallCollisions &&
           sameBits(counters.wallImpulse, other.counters.wallImpulse) &&
           sameBits(counters.dragLoss, other.counters.dragLoss) &&
           counters.cutShortSteps == other.counters.cutShortSteps && sameBits(time, other.time) &&
           steps == other.steps && sameBits(energyResidual, other.energyResidual);
  }
};

class Rewind : public ::testing::TestWithParam<BackendInfo> {
 protected:
  RunSpec spec() const { return parseRunSpec(GetParam().name); }
};

std::string backendName(const ::testing::TestParamInfo<BackendInfo>& info) {
  return std::string(info.param.name);
}

// Every backend, with an attractor pulling for part of the run (its forces are re-applied as
// they were): rewound to a kept moment, the runs step through the very states they had.
TEST_P(Rewind, RewindingThenSteppingRepeatsTheRunBitForBit) {
  RunGroup group(fallingGas(), {spec()}, makeBackend);
  group.setBaseline(true);
  group.setHistoryBound(RunHistory::kDefaultBound);
  std::vector<Snapshot> runStates;
  std::vector<Snapshot> baselineStates;
  for (int step = 0; step < 90; ++step) {
    if (step == 20) group.addAttractor({8.0, 6.0});
    if (step == 50) group.clearAttractors();
    group.step();
    runStates.emplace_back(group.run(0));
    baselineStates.emplace_back(*group.baseline());
  }
  const RunHistory& history = *group.history();
  ASSERT_EQ(history.size(), 16u);          // t = 0, then every 6 steps up to step 90
  EXPECT_LT(history.bytes(), 512u << 10);  // the first state and the logged forces

  group.rewindTo(4);               // step 24, while the attractor pulled
  group.addAttractor({8.0, 6.0});  // the tools are what the user holds now: as then
  ASSERT_EQ(group.steps(), 24u);
  EXPECT_TRUE(Snapshot(group.run(0)) == runStates[23]);
  EXPECT_TRUE(Snapshot(*group.baseline()) == baselineStates[23]);
  for (std::size_t step = 24; step < 90; ++step) {
    if (step == 50) group.clearAttractors();
    group.step();
    EXPECT_TRUE(Snapshot(group.run(0)) == runStates[step]) << "step " << step + 1;
    EXPECT_TRUE(Snapshot(*group.baseline()) == baselineStates[step]) << "step " << step + 1;
  }
}

// Every backend, anchored every 60 steps (the least; RunHistory::kMinStepsPerAnchor): a rewind
// re-steps from the latest anchor before its moment, whose reload the runs had too, and a run
// continued after a rewind reaches the next anchor as before.
TEST_P(Rewind, AcrossAnchorsRewindingThenSteppingRepeatsTheRunBitForBit) {
  RunGroup group(fallingGas(), {spec()}, makeBackend);
  group.setBaseline(true);
  group.setHistoryBound(RunHistory::kDefaultBound, 1);
  std::vector<Snapshot> runStates;
  std::vector<Snapshot> baselineStates;
  const auto step = [&](std::size_t steps) {
    if (steps == 20) group.addAttractor({8.0, 6.0});
    if (steps == 150) group.clearAttractors();
    group.step();
    if (runStates.size() < group.steps()) {
      runStates.emplace_back(group.run(0));
      baselineStates.emplace_back(*group.baseline());
    }
  };
  for (std::size_t steps = 0; steps < 200; ++steps)
    step(steps);
  const RunHistory& history = *group.history();
  ASSERT_EQ(history.anchorCount(), 4u);  // at steps 0, 60, 120 and 180

  for (const std::size_t moment : {25u, 11u, 33u}) {  // steps 150, 66, 198: each past an anchor
    group.rewindTo(moment);
    const std::size_t steps = group.steps();
    ASSERT_EQ(steps, 6 * moment);
    EXPECT_TRUE(Snapshot(group.run(0)) == runStates[steps - 1]) << "moment " << moment;
    EXPECT_TRUE(Snapshot(*group.baseline()) == baselineStates[steps - 1]) << "moment " << moment;
  }
  group.rewindTo(16);  // step 96, with the attractor on: continue through the anchors again
  group.addAttractor({8.0, 6.0});
  for (std::size_t steps = 96; steps < 200; ++steps) {
    step(steps);
    EXPECT_TRUE(Snapshot(group.run(0)) == runStates[steps]) << "step " << steps + 1;
    EXPECT_TRUE(Snapshot(*group.baseline()) == baselineStates[steps]) << "step " << steps + 1;
  }
  EXPECT_EQ(history.anchorCount(), 4u);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, Rewind, ::testing::ValuesIn(registeredBackends()),
                         backendName);

std::unique_ptr<RunGroup> elasticGroup(std::size_t historyBytes) {
  auto group =
      std::make_unique<RunGroup>(fallingGas(), std::vector{parseRunSpec("elastic")}, makeBackend);
  group->setHistoryBound(historyBytes);
  return group;
}

// An attractor's forces, logged every step for 203 balls (3.2 kB a step), outgrow a bound of
// 64 kB within 20 steps: the history starts afresh from now, and never holds more.
TEST(RewindHistory, StartsAfreshFromNowWhenItOutgrowsItsBound) {
  constexpr std::size_t kBound = 64 << 10;
  const auto owner = elasticGroup(kBound);
  RunGroup& group = *owner;
  group.addAttractor({8.0, 6.0});
  bool startedAfresh = false;
  for (int step = 0; step < 300; ++step) {
    group.step();
    ASSERT_LE(group.history()->bytes(), kBound) << "step " << step + 1;
    startedAfresh = startedAfresh || group.history()->time(0) > 0.0;
  }
  EXPECT_TRUE(startedAfresh);
  // Rewinding within the new history is still exact: back to its first moment and on.
  const Snapshot now(group.run(0));
  group.rewindTo(0);
  while (group.steps() < now.steps)
    group.step();
  EXPECT_TRUE(Snapshot(group.run(0)) == now);
}

TEST(RewindHistory, ContinuingAfterARewindDropsTheFuture) {
  const auto owner = elasticGroup(RunHistory::kDefaultBound);
  RunGroup& group = *owner;
  for (int step = 0; step < 60; ++step)
    group.step();
  ASSERT_EQ(group.history()->size(), 11u);
  group.rewindTo(3);
  EXPECT_EQ(group.history()->position(), 3u);
  EXPECT_EQ(group.history()->size(), 11u);  // still there to scrub forward to
  group.rewindTo(8);
  EXPECT_EQ(group.steps(), 48u);
  group.rewindTo(3);
  group.step();
  EXPECT_EQ(group.history()->size(), 4u);  // moments 0-3; the next is 6 steps after moment 3
  EXPECT_EQ(group.steps(), 19u);
  EXPECT_LE(group.history()->time(group.history()->size() - 1), group.time());
}

TEST(RewindHistory, StepBackKeepsNowAndGoesOneMomentBack) {
  const auto owner = elasticGroup(RunHistory::kDefaultBound);
  RunGroup& group = *owner;
  for (int step = 0; step < 15; ++step)
    group.step();
  const Snapshot now(group.run(0));
  group.stepBack();  // moments at 0, 6, 12, and now (15) kept first
  EXPECT_EQ(group.steps(), 12u);
  group.stepBack();
  EXPECT_EQ(group.steps(), 6u);
  group.rewindTo(group.history()->size() - 1);
  EXPECT_TRUE(Snapshot(group.run(0)) == now);
}

TEST(RewindHistory, CompareRunsAndTheBaselineRewindTogether) {
  RunGroup group(fallingGas(), {parseRunSpec("elastic"), parseRunSpec("box2d")}, makeBackend);
  group.setBaseline(true);
  group.setHistoryBound(RunHistory::kDefaultBound);
  std::vector<std::vector<Snapshot>> states(3);
  for (int step = 0; step < 30; ++step) {
    group.step();
    states[0].emplace_back(group.run(0));
    states[1].emplace_back(group.run(1));
    states[2].emplace_back(*group.baseline());
  }
  group.rewindTo(2);  // step 12
  EXPECT_TRUE(Snapshot(group.run(0)) == states[0][11]);
  EXPECT_TRUE(Snapshot(group.run(1)) == states[1][11]);
  EXPECT_TRUE(Snapshot(*group.baseline()) == states[2][11]);
}

TEST(RewindHistory, AnEditStartsANewHistory) {
  const auto owner = elasticGroup(RunHistory::kDefaultBound);
  RunGroup& group = *owner;
  for (int step = 0; step < 30; ++step)
    group.step();
  WorldSettings world = group.world();
  world.gravity = {0.0, -1.0};
  group.setWorld(world);
  EXPECT_EQ(group.history()->size(), 1u);
  EXPECT_EQ(group.history()->time(0), group.time());
}

// The steps between anchors: a bounded re-step at any scene size, from the budget of ball-steps
// down to the least of 60 steps.
TEST(RewindHistory, AnchorsComeEveryBudgetOfBallStepsAndNoCloserThanTheLeast) {
  RunHistory history;
  EXPECT_EQ(history.stepsPerAnchor(38), 52'632u);  // 2e6 / 38 ball-steps, rounded up
  EXPECT_EQ(history.stepsPerAnchor(10'000), 200u);
  EXPECT_EQ(history.stepsPerAnchor(1'000'000), RunHistory::kMinStepsPerAnchor);
  EXPECT_EQ(history.stepsPerAnchor(0), RunHistory::kDefaultBallStepsPerAnchor);
}

// Anchored every 60 steps and bounded to about two anchors: the oldest anchor goes with the
// moments before the next, the rest of the history stays, and rewinding within it is exact.
TEST(RewindHistory, OverItsBoundTheOldestAnchorGoesAndTheLaterMomentsStay) {
  const std::size_t oneAnchor = elasticGroup(RunHistory::kDefaultBound)->history()->bytes();
  auto owner =
      std::make_unique<RunGroup>(fallingGas(), std::vector{parseRunSpec("elastic")}, makeBackend);
  RunGroup& group = *owner;
  group.setHistoryBound(oneAnchor * 5 / 2, 1);
  for (int step = 0; step < 300; ++step) {
    group.step();
    ASSERT_LE(group.history()->bytes(), oneAnchor * 5 / 2) << "step " << step + 1;
  }
  const RunHistory& history = *group.history();
  EXPECT_EQ(history.anchorCount(), 2u);  // at steps 240 and 300
  EXPECT_EQ(history.time(0), 240 * group.dt());
  EXPECT_EQ(history.size(), 11u);  // steps 240 to 300, every 6
  const Snapshot now(group.run(0));
  group.rewindTo(0);
  while (group.steps() < now.steps)
    group.step();
  EXPECT_TRUE(Snapshot(group.run(0)) == now);
}

TEST(RewindHistory, NoneIsKeptUnlessAsked) {
  const auto owner = elasticGroup(0);
  RunGroup& group = *owner;
  group.step();
  EXPECT_EQ(group.history(), nullptr);
}

}  // namespace
}  // namespace fooball
