// RunGroup: 1 to 8 runs of one scene in lockstep, and the chaos baseline (DESIGN.md, "Runs, run
// specs and run groups"). What a run group promises is sameness: the same start, dt, steps, tool
// forces and edits in every run (and in the baseline), so that any difference between runs is
// the methods'. Most runs here use the elastic backend, which is deterministic and integrates
// free flight exactly, so two runs of one spec must agree to the last bit.

#include "fooball/run_group.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend_factory.h"
#include "backend_state.h"
#include "fooball/presets.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "forwarding_backend.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::copyOf;
using testing::emptyBox;
using testing::gas;
using ::testing::HasSubstr;
using testing::kDt;
using testing::makeBackend;
using testing::threeBalls;

std::vector<RunSpec> specsOf(std::initializer_list<const char*> texts) {
  std::vector<RunSpec> specs;
  for (const char* text : texts)
    specs.push_back(parseRunSpec(text));
  return specs;
}

RunGroup groupOf(const Scene& scene, std::initializer_list<const char*> texts) {
  return RunGroup(scene, specsOf(texts), &makeBackend);
}

/// Every run of the group, then the baseline if there is one.
std::vector<const Simulation*> everySimulation(const RunGroup& group) {
  std::vector<const Simulation*> simulations;
  for (std::size_t i = 0; i < group.runCount(); ++i)
    simulations.push_back(&group.run(i));
  if (group.baseline() != nullptr) simulations.push_back(group.baseline());
  return simulations;
}

void expectBitwiseSame(const Simulation& a, const Simulation& b) {
  ASSERT_EQ(a.ballCount(), b.ballCount());
  for (std::size_t i = 0; i < a.ballCount(); ++i) {
    EXPECT_EQ(a.positions()[i], b.positions()[i]) << "ball " << i;
    EXPECT_EQ(a.velocities()[i], b.velocities()[i]) << "ball " << i;
  }
}

// --- lockstep -------------------------------------------------------------------------------

TEST(RunGroup, EveryRunTakesTheSameStepsToTheSameTime) {
  // Every registered backend, in groups as large as a run group allows, each with a second
  // elastic run of other options.
  const auto backends = registeredBackends();
  for (std::size_t first = 0; first < backends.size(); first += RunGroup::kMaxRuns - 1) {
    std::vector<RunSpec> specs;
    for (std::size_t i = first; i < std::min(backends.size(), first + RunGroup::kMaxRuns - 1); ++i)
      specs.push_back({std::string(backends[i].name), {}});
    specs.push_back(parseRunSpec("elastic:substeps=1"));
    RunGroup group(gas(40), specs, &makeBackend);
    group.setBaseline(true);
    group.setDt(0.01);
    for (int i = 0; i < 37; ++i)
      group.step();
    group.runFor(0.5);  // 50 more
    EXPECT_EQ(group.steps(), 87u);
    for (const Simulation* simulation : everySimulation(group)) {
      EXPECT_EQ(simulation->steps(), 87u);
      EXPECT_EQ(simulation->dt(), 0.01);
      EXPECT_EQ(simulation->time(), group.time());  // bitwise: time is steps·dt in every run
    }
    EXPECT_EQ(group.time(), 87 * 0.01);
    // One label per run, its spec.
    std::vector<std::string> labels;
    for (const RunSpec& spec : specs)
      labels.push_back(spec.text());
    EXPECT_EQ(group.labels(), labels);
  }
}

TEST(RunGroup, IdenticalSpecsDivergeByExactlyZero) {
  // Determinism is in every backend's contract: two runs of one spec in one group must stay
  // bit for bit the same through ten simulated seconds of a gas (hundreds of collisions).
  for (const BackendInfo& info : registeredBackends()) {
    SCOPED_TRACE(std::string(info.name));
    const std::string name(info.name);
    RunGroup group(gas(100), {RunSpec{name, {}}, RunSpec{name, {}}}, &makeBackend);
    group.runFor(10.0);
    ASSERT_GT(group.run(1).counters().ballCollisions, 100u);
    const Divergence divergence = group.divergence(1);
    EXPECT_EQ(divergence.rmsPositionDifference, 0.0);
    EXPECT_EQ(divergence.maxPositionDifference, 0.0);
    EXPECT_EQ(divergence.energyDifference, 0.0);
    EXPECT_EQ(divergence.momentumDifference, 0.0);
    expectBitwiseSame(group.run(0), group.run(1));
  }
}

TEST(RunGroup, DifferentOptionsDivergeAndRunZeroIsTheReference) {
  RunGroup group = groupOf(gas(100), {"elastic", "elastic:substeps=1"});
  group.runFor(3.0);
  EXPECT_EQ(group.divergence(0).rmsPositionDifference, 0.0);
  EXPECT_GT(group.divergence(1).rmsPositionDifference, 0.0);
  EXPECT_GE(group.divergence(1).maxPositionDifference, group.divergence(1).rmsPositionDifference);
}

TEST(RunGroup, HoldsOneToEightRunsAndRefusesANinth) {
  EXPECT_THROW(RunGroup(threeBalls(), {}, &makeBackend), std::invalid_argument);
  const std::vector<RunSpec> nine(RunGroup::kMaxRuns + 1, parseRunSpec("elastic"));
  EXPECT_THROW(RunGroup(threeBalls(), nine, &makeBackend), std::invalid_argument);

  const std::vector<RunSpec> eight(RunGroup::kMaxRuns, parseRunSpec("elastic"));
  RunGroup group(threeBalls(), eight, &makeBackend);
  group.setBaseline(true);
  group.runFor(1.0);
  EXPECT_EQ(group.runCount(), 8u);
  for (std::size_t i = 0; i < group.runCount(); ++i)
    EXPECT_EQ(group.divergence(i).rmsPositionDifference, 0.0) << "run " << i;
  EXPECT_THROW(group.addRun(parseRunSpec("elastic")), std::invalid_argument);
  EXPECT_EQ(group.runCount(), 8u);
  EXPECT_EQ(group.time(), 60 * kDt) << "a refused run changes nothing";
}

TEST(RunGroup, ABadSpecIsRefusedNamingItAndChangesNothing) {
  EXPECT_THAT(
      [] {
        groupOf(threeBalls(), {"elastic", "elastic:warp_factor=9"});
      },
      ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("elastic:warp_factor=9")));
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  group.runFor(0.5);
  EXPECT_THROW(group.addRun(parseRunSpec("warp-drive")), std::invalid_argument);
  EXPECT_THROW(group.setSpec(0, parseRunSpec("elastic:substeps=0")), std::invalid_argument);
  EXPECT_EQ(group.runCount(), 1u);
  EXPECT_EQ(group.spec(0).text(), "elastic");
  EXPECT_EQ(group.steps(), 30u);
}

TEST(RunGroup, AddRunStartsItFromRunZeroNowAndTimeCarriesOn) {
  RunGroup group = groupOf(gas(40), {"elastic"});
  group.runFor(1.0);
  group.addRun(parseRunSpec("elastic:substeps=2"));
  ASSERT_EQ(group.runCount(), 2u);
  expectBitwiseSame(group.run(0), group.run(1));
  EXPECT_EQ(group.run(1).time(), 1.0);
  EXPECT_EQ(group.run(0).time(), 1.0);
}

TEST(RunGroup, RemovingRunZeroMakesRunOneTheReference) {
  RunGroup group = groupOf(gas(40), {"elastic", "elastic:substeps=1", "elastic:substeps=2"});
  group.setBaseline(true);
  group.runFor(2.0);
  const std::vector<Vec2> second = copyOf(group.run(1).positions());
  group.removeRun(0);
  ASSERT_EQ(group.runCount(), 2u);
  EXPECT_EQ(group.spec(0).text(), "elastic:substeps=1");
  EXPECT_EQ(copyOf(group.run(0).positions()), second) << "the others carry on";
  EXPECT_EQ(group.divergence(0).rmsPositionDifference, 0.0);
  // The baseline follows the new reference: restarted from it, displaced.
  ASSERT_NE(group.baseline(), nullptr);
  EXPECT_EQ(group.baseline()->backend().options().value("substeps"), 1.0);
  EXPECT_NEAR(group.baselineDivergence()->rmsPositionDifference, RunGroup::kBaselineDisplacement,
              1e-14);
}

// --- tools and edits reach every run and the baseline ------------------------------------------

TEST(RunGroup, AnAttractorPullsEveryRunAndTheBaselineAlike) {
  RunGroup pulled = groupOf(gas(40), {"elastic", "elastic"});
  RunGroup free = groupOf(gas(40), {"elastic"});
  pulled.setBaseline(true);
  pulled.addAttractor({8.0, 4.5});
  pulled.runFor(1.0);
  free.runFor(1.0);
  for (const Simulation* simulation : everySimulation(pulled)) {
    ASSERT_EQ(simulation->interactions.attractors().size(), 1u);
    // The attractor does work on the gas, and the budget books it.
    EXPECT_GT(std::abs(simulation->metrics().externalWork), 1.0);
    EXPECT_GT(measureDivergence(free.run(0), *simulation).rmsPositionDifference, 0.01);
  }
  expectBitwiseSame(pulled.run(0), pulled.run(1));
  pulled.clearAttractors();
  for (const Simulation* simulation : everySimulation(pulled))
    EXPECT_TRUE(simulation->interactions.attractors().empty());
}

TEST(RunGroup, AGrabTakesTheSameBallInEveryRunAndTheBaseline) {
  Scene scene = threeBalls();
  RunGroup group = groupOf(scene, {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.setMouseMode(MouseMode::Grab);
  group.setScope(Scope::Nearest);
  group.pressTool({8.2, 2.1});  // next to ball 1
  group.moveTool({8.0, 7.0});
  group.runFor(1.0);
  for (const Simulation* simulation : everySimulation(group)) {
    EXPECT_EQ(simulation->interactions.mode, MouseMode::Grab);
    EXPECT_TRUE(simulation->interactions.pressed());
    EXPECT_EQ(simulation->interactions.target(), std::optional<std::size_t>(1));
    // Pulled up towards the cursor from y = 2 (it drifted 0.5 m up on its own).
    EXPECT_GT(simulation->positions()[1].y, 4.0);
  }
  group.releaseTool({8.0, 7.0});
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_FALSE(simulation->interactions.pressed());
}

TEST(RunGroup, SetBallReachesEveryRunAndTheBaseline) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(0.5);
  const BallDef edited{{6.0, 7.0}, {-1.0, -1.0}, 0.25, 3.0, 0x123456};
  group.setBall(1, edited);
  for (const Simulation* simulation : everySimulation(group)) {
    EXPECT_EQ(simulation->positions()[1], edited.position);
    EXPECT_EQ(simulation->velocities()[1], edited.velocity);
    EXPECT_EQ(simulation->radii()[1], edited.radius);
    EXPECT_EQ(simulation->masses()[1], edited.mass);
    EXPECT_EQ(simulation->colours()[1], edited.color);
  }
  EXPECT_EQ(group.ball(1).position, edited.position);
}

TEST(RunGroup, ASetBallThatFailsInOneRunChangesNoRun) {
  // Two methods apart for long enough that their balls are in different places: a ball put
  // where run 1 has another ball but run 0 has room succeeds in run 0 and fails in run 1, and
  // must then be undone in run 0.
  RunGroup group = groupOf(gas(60), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(6.0);
  const Simulation& reference = group.run(0);
  const Simulation& other = group.run(1);
  constexpr std::size_t kMoved = 0;
  std::optional<BallDef> blocked;
  for (std::size_t j = 1; j < other.ballCount() && !blocked; ++j) {
    const BallDef candidate{other.positions()[j], {}, other.radii()[j], 1.0, 0xffffff};
    bool roomInRunZero = true;
    for (std::size_t k = 0; k < reference.ballCount(); ++k) {
      if (k == kMoved) continue;
      const double clearance = candidate.radius + reference.radii()[k] + 0.05;  // well clear
      if (length(reference.positions()[k] - candidate.position) < clearance) roomInRunZero = false;
    }
    if (roomInRunZero) blocked = candidate;
  }
  ASSERT_TRUE(blocked) << "no place that is free in run 0 but taken in run 1";

  std::vector<Scene> before;
  for (const Simulation* simulation : everySimulation(group))
    before.push_back(simulation->scene());
  std::vector<double> work;
  for (const Simulation* simulation : everySimulation(group))
    work.push_back(simulation->metrics().externalWork);
  EXPECT_THROW(group.setBall(kMoved, *blocked), SceneError);
  const std::vector<const Simulation*> simulations = everySimulation(group);
  for (std::size_t s = 0; s < simulations.size(); ++s) {
    SCOPED_TRACE("simulation " + std::to_string(s));
    const Scene now = simulations[s]->scene();
    ASSERT_EQ(now.balls.size(), before[s].balls.size());
    for (std::size_t i = 0; i < now.balls.size(); ++i) {
      EXPECT_EQ(now.balls[i].position, before[s].balls[i].position) << "ball " << i;
      EXPECT_EQ(now.balls[i].velocity, before[s].balls[i].velocity) << "ball " << i;
      EXPECT_EQ(now.balls[i].radius, before[s].balls[i].radius) << "ball " << i;
      EXPECT_EQ(now.balls[i].mass, before[s].balls[i].mass) << "ball " << i;
      EXPECT_EQ(now.balls[i].color, before[s].balls[i].color) << "ball " << i;
    }
    // Undoing books the energy back: the budget is where it was, to rounding.
    EXPECT_NEAR(simulations[s]->metrics().externalWork, work[s], 1e-12);
  }
}

TEST(RunGroup, EditBallScalesTheMassWithTheAreaUntilTheMassIsChosen) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "exact"});
  const double mass = group.ball(0).mass;
  BallDef bigger = group.ball(0);
  bigger.radius = 1.0;  // from 0.5: twice the radius, four times the area
  EXPECT_EQ(group.editBall(0, bigger).mass, 4.0 * mass);
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_EQ(simulation->masses()[0], 4.0 * mass);
  EXPECT_FALSE(group.massChosen(0));

  BallDef heavier = group.ball(0);
  heavier.mass = 2.5;
  group.editBall(0, heavier);
  EXPECT_TRUE(group.massChosen(0));
  BallDef smaller = group.ball(0);
  smaller.radius = 0.25;
  EXPECT_EQ(group.editBall(0, smaller).mass, 2.5) << "a chosen mass stays";
  EXPECT_EQ(group.run(1).masses()[0], 2.5);

  // The fact follows the ball: ball 0 deleted, the ball that was 1 is 0 and its mass follows
  // its radius; the deleted ball comes back with its chosen mass.
  const BallStates deleted = group.ballStates(0);
  group.deleteBall(0);
  EXPECT_FALSE(group.massChosen(0));
  group.restoreBall(0, deleted, BallPlacement::Insert);
  EXPECT_TRUE(group.massChosen(0));
  EXPECT_FALSE(group.massChosen(1));
}

/// Every simulation's balls, time and counters, for bit-exact comparison.
struct GroupState {
  std::vector<Scene> scenes;
  std::vector<double> times;
  std::vector<std::uint64_t> wallCollisions;
};

GroupState stateOf(const RunGroup& group) {
  GroupState state;
  for (const Simulation* simulation : everySimulation(group)) {
    state.scenes.push_back(simulation->scene());
    state.times.push_back(simulation->time());
    state.wallCollisions.push_back(simulation->counters().wallCollisions);
  }
  return state;
}

void expectSameState(const GroupState& a, const GroupState& b) {
  ASSERT_EQ(a.scenes.size(), b.scenes.size());
  for (std::size_t s = 0; s < a.scenes.size(); ++s) {
    SCOPED_TRACE("simulation " + std::to_string(s));
    ASSERT_EQ(a.scenes[s].balls.size(), b.scenes[s].balls.size());
    for (std::size_t i = 0; i < a.scenes[s].balls.size(); ++i) {
      const BallDef& x = a.scenes[s].balls[i];
      const BallDef& y = b.scenes[s].balls[i];
      EXPECT_EQ(x.position, y.position) << "ball " << i;
      EXPECT_EQ(x.velocity, y.velocity) << "ball " << i;
      EXPECT_EQ(x.radius, y.radius) << "ball " << i;
      EXPECT_EQ(x.mass, y.mass) << "ball " << i;
      EXPECT_EQ(x.color, y.color) << "ball " << i;
    }
    EXPECT_EQ(a.times[s], b.times[s]);
    EXPECT_EQ(a.wallCollisions[s], b.wallCollisions[s]);
  }
}

TEST(RunGroup, RestoreBallPutsBackEachRunsOwnStateBitExactly) {
  // Two methods apart for long enough that ball 5 is somewhere else in each run.
  RunGroup group = groupOf(gas(40), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(3.0);
  ASSERT_NE(group.run(0).positions()[5], group.run(1).positions()[5]);
  const GroupState before = stateOf(group);
  const BallStates saved = group.ballStates(5);
  ASSERT_EQ(saved.states.size(), 3u) << "two runs and the baseline";

  group.deleteBall(5);
  EXPECT_EQ(group.ballCount(), 39u);
  group.restoreBall(5, saved, BallPlacement::Insert);
  expectSameState(stateOf(group), before);

  BallDef moved = group.ball(5);
  moved.velocity = {9.0, 0.0};
  group.editBall(5, moved);
  group.restoreBall(5, saved, BallPlacement::Replace);
  expectSameState(stateOf(group), before);
}

TEST(RunGroup, ABallThatNoLongerFitsIsNotPutBackAndNothingChanges) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "exact"});
  const BallStates deleted = group.ballStates(0);
  group.deleteBall(0);
  BallDef intruder = group.ball(0);  // the ball that was 1, now 0, onto the deleted ball's place
  intruder.position = deleted.states[0].position;
  group.setBall(0, intruder);
  const GroupState before = stateOf(group);

  const auto problem = group.findRestoreProblem(0, deleted, BallPlacement::Insert);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->kind, BallProblem::Kind::Overlaps);
  EXPECT_EQ(problem->otherBall, 0u);
  try {
    group.restoreBall(0, deleted, BallPlacement::Insert);
    ADD_FAILURE() << "put back onto another ball";
  } catch (const BallError& error) {
    EXPECT_EQ(plainWords(error.problem()), "The ball would overlap ball 0 (by " +
                                               std::to_string(std::lround(100.0 * problem->value)) +
                                               "% of the smaller radius).");
  }
  expectSameState(stateOf(group), before);
}

TEST(RunGroup, SetBallCountAddsTheSameBallsToEveryRunAndRemovesTheNewest) {
  RunGroup group = groupOf(gas(30), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(2.0);  // the runs differ now: new balls must clear both
  ASSERT_GT(group.divergence(1).rmsPositionDifference, 0.0);
  group.setBallCount(50);
  EXPECT_EQ(group.ballCount(), 50u);
  EXPECT_EQ(group.newBallScale(), 1.0) << "a sparse gas has room for full-size balls";
  for (const Simulation* simulation : everySimulation(group)) {
    ASSERT_EQ(simulation->ballCount(), 50u);
    for (std::size_t i = 30; i < 50; ++i) {
      EXPECT_EQ(simulation->positions()[i], group.run(0).positions()[i]) << "ball " << i;
      EXPECT_EQ(simulation->velocities()[i], group.run(0).velocities()[i]) << "ball " << i;
      EXPECT_EQ(simulation->colours()[i], defaultBallColor(i)) << "ball " << i;
    }
  }
  // Valid in every run: no new ball overlaps a ball of any run.
  for (const Simulation* simulation : everySimulation(group)) {
    Scene state = simulation->scene();
    EXPECT_NO_THROW(validateScene(state, "after setBallCount"));
  }
  const std::vector<Vec2> kept = copyOf(group.run(1).positions().subspan(0, 20));
  group.setBallCount(20);
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_EQ(simulation->ballCount(), 20u);
  EXPECT_EQ(copyOf(group.run(1).positions()), kept) << "the first 20 stay as they were";
  group.runFor(0.5);
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_EQ(simulation->steps(), group.steps());
}

TEST(RunGroup, ThousandsOfNewBallsInTheDefaultPresetOverlapNothingBeforeTheFirstStep) {
  // Issue 38: 5,000 small balls added to the default preset's 38 (radii 0.2–1 m) showed an
  // overlap of 856%. They go to lattice cells no ball reaches into, scaled to the free area.
  RunGroup group = groupOf(loadPreset("default"), {"elastic"});
  group.setBallCount(38 + 5'000);
  ASSERT_EQ(group.ballCount(), 5'038u);
  EXPECT_LT(group.newBallScale(), 1.0) << "they had to be smaller to fit";
  EXPECT_EQ(group.run(0).metrics().maxOverlap, 0.0);
  EXPECT_NO_THROW(validateScene(group.run(0).scene(), "after setBallCount"));
}

TEST(RunGroup, MostBallsThatFitIsTheLargestCountSetBallCountTakes) {
  // Two runs and the baseline, moved on: new balls must clear every copy's balls.
  RunGroup group = groupOf(gas(3, 7, 1.0, 1.0), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(1.0);
  const std::size_t most = group.mostBallsThatFit();
  // New balls shrink to 1% of the largest ball there at most, one per lattice cell of side
  // 2·r/0.8: by area, at most 0.16 · (free area) / r² beside the 3 balls (r = 1% of the largest).
  double free = 1.0;
  double largest = 0.0;
  for (const BallDef& ball : group.run(0).scene().balls) {
    free -= std::numbers::pi * ball.radius * ball.radius;
    largest = std::max(largest, ball.radius);
  }
  const double smallest = 0.01 * largest;
  EXPECT_GT(most, 100u);
  EXPECT_LE(double(most), 3.0 + 0.16 * free / (smallest * smallest));
  EXPECT_THROW(group.setBallCount(most + 1), SceneError) << "at most " << most;
  EXPECT_EQ(group.ballCount(), 3u) << "a refused count changes nothing";
  group.setBallCount(most);
  EXPECT_EQ(group.ballCount(), most);
}

TEST(RunGroup, RestartKeepsTheBallCountAndGivesTheSameStateEachTime) {
  const Scene loaded = gas(30);
  RunGroup group = groupOf(loaded, {"elastic", "exact"});
  group.setBaseline(true);
  group.setBallCount(50);
  group.runFor(1.0);
  group.restart();
  EXPECT_EQ(group.time(), 0.0);
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_EQ(simulation->ballCount(), 50u);
  for (std::size_t i = 0; i < 30; ++i)
    EXPECT_EQ(group.run(0).positions()[i], loaded.balls[i].position)
        << "the loaded balls, at t = 0";
  const std::vector<Vec2> first = copyOf(group.run(1).positions());
  group.runFor(0.5);
  group.restart();
  EXPECT_EQ(copyOf(group.run(1).positions()), first) << "every restart starts the same";
  group.setBallCount(10);
  group.restart();
  EXPECT_EQ(group.ballCount(), 10u) << "fewer balls: the newest stay removed";
}

TEST(RunGroup, DeleteBallRemovesItFromEveryRunAndTheBaseline) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.setSelected(2);
  group.runFor(0.5);
  std::vector<Vec2> lastBall;
  for (const Simulation* simulation : everySimulation(group))
    lastBall.push_back(simulation->positions()[2]);
  group.deleteBall(1);
  const std::vector<const Simulation*> simulations = everySimulation(group);
  for (std::size_t s = 0; s < simulations.size(); ++s) {
    ASSERT_EQ(simulations[s]->ballCount(), 2u);
    EXPECT_EQ(simulations[s]->positions()[1], lastBall[s]) << "ball 2 is ball 1 now";
    EXPECT_EQ(simulations[s]->colours()[1], 0x0000ffu);
    EXPECT_EQ(simulations[s]->interactions.selected, std::nullopt);
  }
}

TEST(RunGroup, SetWorldAndSetDtReachEveryRunAndTheBaseline) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  WorldSettings world = group.world();
  world.gravity = {0.0, -9.81};
  world.airResistance = 0.2;
  world.walls.top = false;
  group.setWorld(world);
  group.setDt(0.005);
  for (const Simulation* simulation : everySimulation(group)) {
    EXPECT_EQ(simulation->world(), world);
    EXPECT_EQ(simulation->dt(), 0.005);
  }
  group.runFor(0.5);
  for (const Simulation* simulation : everySimulation(group)) {
    EXPECT_EQ(simulation->steps(), 100u);
    EXPECT_LT(simulation->velocities()[2].y, -1.5 - 9.81 * 0.3) << "falls under gravity";
  }
}

// --- the chaos baseline ----------------------------------------------------------------------

TEST(RunGroup, TheBaselineStartsDisplacedByExactlyTheStatedDistance) {
  RunGroup group = groupOf(gas(300), {"elastic", "exact"});
  EXPECT_FALSE(group.hasBaseline());
  EXPECT_EQ(group.baselineDivergence(), std::nullopt);
  group.setBaseline(true);
  ASSERT_TRUE(group.hasBaseline());
  // Every ball moved 1e-9 m: RMS and largest difference are 1e-9 m up to the rounding of
  // positions of up to 16 m (16·2⁻⁵³ ≈ 2e-15 m per coordinate).
  const Divergence start = *group.baselineDivergence();
  EXPECT_NEAR(start.rmsPositionDifference, RunGroup::kBaselineDisplacement, 1e-14);
  EXPECT_NEAR(start.maxPositionDifference, RunGroup::kBaselineDisplacement, 1e-14);
  EXPECT_EQ(group.baseline()->time(), group.time());
  EXPECT_EQ(group.baseline()->backend().options().value("substeps"),
            group.run(0).backend().options().value("substeps"))
      << "a copy of run 0's method";
  // It is hidden: not a run, no label.
  EXPECT_EQ(group.runCount(), 2u);
  EXPECT_EQ(group.labels().size(), 2u);
  group.setBaseline(false);
  EXPECT_EQ(group.baseline(), nullptr);
}

TEST(RunGroup, TheBaselineStaysNearRunZeroHeadOn) {
  // Two balls head-on are no chaotic gas: the baseline's 1e-9 m offsets make the one collision
  // in 5 s (at t = 7/6 s) slightly off-centre, by an impact parameter b ≤ 2e-9 m. The contact
  // normal then tilts by θ = b/(2r) ≤ 2e-9 rad, and each ball leaves with a sideways velocity
  // v_rel·θ ≤ 6 m/s · 2e-9 = 1.2e-8 m/s: the difference grows linearly, to at most
  // 1e-9 + 1.2e-8 · (5 − 7/6) ≈ 4.7e-8 m by t = 5 s (the next collision is at 35/6 s). The
  // bound below adds 1e-9 m for the timing shift of the collision and rounding.
  //
  // The preset's balls touch exactly at the end of a step. A time-stepped method detects the
  // contact at a step boundary, so there an offset of any size moves the collision by a whole
  // substep (elastic: 3 m/s · dt/4 = 0.0125 m per ball at once): for elastic the start is
  // moved 1 cm so that the contact falls inside a substep, as it does in any scene not built to
  // touch on the clock.
  struct Case {
    const char* reference;
    double shift;  ///< m, of ball 1's start
  };
  for (const Case& test : {Case{"exact", 0.0}, Case{"elastic", 0.01}}) {
    SCOPED_TRACE(test.reference);
    Scene scene = loadPreset("head-on");
    scene.balls[1].position.x += test.shift;
    RunGroup group = groupOf(scene, {test.reference});
    group.setBaseline(true);
    double largest = 0.0;
    for (int step = 0; step < 300; ++step) {
      group.step();
      const double t = group.time();
      const double bound = 2e-9 + 1.2e-8 * std::max(0.0, t - 7.0 / 6.0);
      const double rms = group.baselineDivergence()->rmsPositionDifference;
      ASSERT_LE(rms, bound) << "t = " << t;
      largest = std::max(largest, rms);
    }
    EXPECT_LT(largest, 5e-8);
    EXPECT_GT(largest, RunGroup::kBaselineDisplacement) << "the off-centre hit does show";
    EXPECT_EQ(group.run(0).counters().ballCollisions, 1u);
  }
}

TEST(RunGroup, TheBaselineGrowsByOrdersOfMagnitudeInAGas) {
  // In a gas of 300 balls of radius 0.1 m every collision multiplies a small offset by about
  // (mean free path)/r ≈ 24, and each ball collides about once a second, the fast ones more
  // often: in 2 s the 1e-9 m grow by many orders of magnitude (measured: to ~0.2 m). 1e5-fold is
  // a safe floor that no non-chaotic scene reaches (head-on above: 15-fold in 5 s).
  for (const char* reference : {"elastic", "exact"}) {
    SCOPED_TRACE(reference);
    RunGroup group = groupOf(loadPreset("gas"), {reference});
    group.setBaseline(true);
    group.runFor(2.0);
    EXPECT_GT(group.baselineDivergence()->rmsPositionDifference,
              1e5 * RunGroup::kBaselineDisplacement);
  }
}

TEST(RunGroup, SetSpecOnRunZeroRebuildsTheBaselineFromItsState) {
  RunGroup group = groupOf(gas(100), {"elastic", "elastic"});
  group.setBaseline(true);
  group.runFor(4.0);
  ASSERT_GT(group.baselineDivergence()->rmsPositionDifference,
            10.0 * RunGroup::kBaselineDisplacement);
  group.setSpec(0, parseRunSpec("elastic:substeps=2"));
  EXPECT_EQ(group.spec(0).text(), "elastic:substeps=2");
  EXPECT_EQ(group.run(0).backend().options().value("substeps"), 2.0);
  ASSERT_NE(group.baseline(), nullptr);
  EXPECT_EQ(group.baseline()->backend().options().value("substeps"), 2.0);
  EXPECT_NEAR(group.baselineDivergence()->rmsPositionDifference, RunGroup::kBaselineDisplacement,
              1e-14);
  EXPECT_EQ(group.baseline()->time(), group.time());
  // Run 1 kept its spec and its state.
  EXPECT_EQ(group.divergence(1).rmsPositionDifference, 0.0);
  EXPECT_EQ(group.run(1).backend().options().value("substeps"), 4.0);
}

TEST(RunGroup, SetOptionChangesTheRunItsSpecAndRunZerosBaseline) {
  RunGroup group = groupOf(gas(40), {"elastic", "elastic"});
  group.setBaseline(true);
  group.setOption(0, "substeps", 7.0);
  group.setOption(1, "substeps", 3.0);
  EXPECT_EQ(group.spec(0).text(), "elastic:substeps=7");
  EXPECT_EQ(group.spec(1).text(), "elastic:substeps=3");
  EXPECT_EQ(group.run(0).backend().options().value("substeps"), 7.0);
  EXPECT_EQ(group.baseline()->backend().options().value("substeps"), 7.0);
  EXPECT_THROW(group.setOption(1, "substeps", 0.0), std::invalid_argument);
  EXPECT_EQ(group.spec(1).text(), "elastic:substeps=3");
}

TEST(RunGroup, SynchroniseRestartsEveryRunFromRunZeroWithTimeCarryingOn) {
  RunGroup group = groupOf(gas(60), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  group.runFor(3.0);
  ASSERT_GT(group.divergence(1).rmsPositionDifference, 0.0);
  const std::vector<Vec2> reference = copyOf(group.run(0).positions());
  group.synchronise();
  EXPECT_EQ(copyOf(group.run(0).positions()), reference) << "run 0 is where it was";
  expectBitwiseSame(group.run(0), group.run(1));
  EXPECT_EQ(group.divergence(1).rmsPositionDifference, 0.0);
  EXPECT_NEAR(group.baselineDivergence()->rmsPositionDifference, RunGroup::kBaselineDisplacement,
              1e-14);
  for (const Simulation* simulation : everySimulation(group)) {
    EXPECT_EQ(simulation->time(), 3.0);
    EXPECT_EQ(simulation->counters().ballCollisions, 0u) << "counters start again";
    EXPECT_EQ(simulation->metrics().energyResidual, 0.0) << "so does the budget";
  }
  group.step();
  for (const Simulation* simulation : everySimulation(group))
    EXPECT_EQ(simulation->time(), 3.0 + kDt);
}

TEST(RunGroup, ColoursSurviveASaveAndLoad) {
  RunGroup group = groupOf(threeBalls(), {"elastic", "exact"});
  group.setBallCount(5);
  group.runFor(0.5);
  const std::vector<std::uint32_t> colours(group.colours().begin(), group.colours().end());
  ASSERT_EQ(colours.size(), 5u);
  EXPECT_EQ(colours[0], 0xff0000u);
  EXPECT_EQ(colours[1], 0x00ff00u);
  EXPECT_EQ(colours[2], 0x0000ffu);
  EXPECT_EQ(
      std::vector<std::uint32_t>(group.run(1).colours().begin(), group.run(1).colours().end()),
      colours);

  const Scene loaded = parseScene(writeScene(group.scene()), "saved");
  ASSERT_EQ(loaded.balls.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(loaded.balls[i].color, colours[i]) << "ball " << i;
  RunGroup reopened = groupOf(loaded, {"elastic", "elastic"});
  EXPECT_EQ(std::vector<std::uint32_t>(reopened.colours().begin(), reopened.colours().end()),
            colours);
}

// --- stepping in parts ------------------------------------------------------------------------

TEST(RunGroup, StepsInPartsAreTheSameStepsAsStep) {
  RunGroup whole = groupOf(gas(40), {"elastic", "exact"});
  RunGroup inParts = groupOf(gas(40), {"elastic", "exact"});
  whole.setBaseline(true);
  inParts.setBaseline(true);
  std::vector<BackendStep> steps;
  for (int i = 0; i < 60; ++i) {
    whole.step();
    inParts.beginSteps(steps);
    ASSERT_EQ(steps.size(), 3u) << "one per run and the baseline's";
    EXPECT_TRUE(inParts.stepping());
    for (BackendStep& step : steps)
      step.run();
    inParts.finishSteps(steps);
    EXPECT_FALSE(inParts.stepping());
  }
  expectBitwiseSame(whole.run(0), inParts.run(0));
  expectBitwiseSame(whole.run(1), inParts.run(1));
  expectBitwiseSame(*whole.baseline(), *inParts.baseline());
}

TEST(RunGroup, AbandonedStepsLeaveEveryRunWhereItWasAndTheRunsGoOn) {
  RunGroup group = groupOf(gas(40), {"elastic", "elastic:substeps=1"});
  RunGroup uninterrupted = groupOf(gas(40), {"elastic", "elastic:substeps=1"});
  group.setBaseline(true);
  uninterrupted.setBaseline(true);
  group.runFor(1.0);
  uninterrupted.runFor(1.0);
  std::vector<std::vector<Vec2>> before;
  for (const Simulation* simulation : everySimulation(group))
    before.push_back(copyOf(simulation->positions()));

  std::vector<BackendStep> steps;
  group.beginSteps(steps);
  steps[0].run();  // one finished, the others never ran: all given up all the same
  group.abandonSteps();
  EXPECT_FALSE(group.stepping());
  const std::vector<const Simulation*> simulations = everySimulation(group);
  for (std::size_t s = 0; s < simulations.size(); ++s) {
    EXPECT_EQ(copyOf(simulations[s]->positions()), before[s]) << "simulation " << s;
    EXPECT_EQ(simulations[s]->steps(), 60u);
  }
  EXPECT_EQ(group.spec(1).text(), "elastic:substeps=1") << "fresh backends of the same specs";
  EXPECT_EQ(group.run(1).backend().options().value("substeps"), 1.0);

  // Fresh backends of the same specs, deterministic: on as if nothing had happened.
  group.runFor(1.0);
  uninterrupted.runFor(1.0);
  expectBitwiseSame(group.run(0), uninterrupted.run(0));
  expectBitwiseSame(group.run(1), uninterrupted.run(1));
  expectBitwiseSame(*group.baseline(), *uninterrupted.baseline());
}

/// Forwards to a real backend and throws from its kFailingStep-th step on, as an engine whose
/// process died does (node_host::HostError).
class DyingBackend final : public testing::ForwardingBackend {
 public:
  static constexpr int kFailingStep = 10;
  using ForwardingBackend::ForwardingBackend;
  void step(double dt, std::span<const Vec2> forces) override {
    if (++steps_ >= kFailingStep) throw std::runtime_error("dying: the engine's process died");
    ForwardingBackend::step(dt, forces);
  }

 private:
  int steps_ = 0;
};

/// Runs of "elastic:substeps=1" die at their kFailingStep-th step; every other spec is itself.
std::unique_ptr<Backend> makeDyingBackend(const RunSpec& spec) {
  if (spec.text() != "elastic:substeps=1") return createBackend(spec);
  return std::make_unique<DyingBackend>(createBackend(spec));
}

/// `count` lockstep steps as a threaded driver takes them; the failures finishSteps() reported.
std::vector<RunGroup::StepFailure> stepInParts(RunGroup& group, int count) {
  std::vector<RunGroup::StepFailure> failures;
  std::vector<BackendStep> steps;
  for (int i = 0; i < count; ++i) {
    group.beginSteps(steps);
    for (BackendStep& step : steps)
      step.run();
    for (RunGroup::StepFailure& failure : group.finishSteps(steps))
      failures.push_back(std::move(failure));
  }
  return failures;
}

TEST(RunGroup, ARunWhoseStepFailsIsRemovedWithItsReasonAndTheOthersGoOn) {
  const std::vector<RunSpec> specs = specsOf({"elastic", "elastic:substeps=1", "exact"});
  RunGroup group(gas(40), specs, &makeDyingBackend);
  RunGroup untouched = groupOf(gas(40), {"elastic", "exact"});
  group.setBaseline(true);
  const std::vector<RunGroup::StepFailure> failures = stepInParts(group, 20);
  untouched.runFor(20 * kDt);

  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].run, std::optional<std::size_t>(1));
  EXPECT_EQ(failures[0].label, "elastic:substeps=1");
  EXPECT_EQ(failures[0].message, "dying: the engine's process died");
  ASSERT_EQ(group.runCount(), 2u);
  EXPECT_EQ(group.spec(0).text(), "elastic");
  EXPECT_EQ(group.spec(1).text(), "exact");
  EXPECT_TRUE(group.hasBaseline()) << "run 0 went on, and so does its baseline";
  EXPECT_FALSE(group.paused());
  EXPECT_EQ(group.steps(), 20u) << "the other runs took every step";
  expectBitwiseSame(untouched.run(0), group.run(0));
  expectBitwiseSame(untouched.run(1), group.run(1));
}

TEST(RunGroup, WhenEveryRunFailsTheyStayWhereTheStepBeganPausedAndGoOnWhenPlayed) {
  RunGroup group(gas(40), specsOf({"elastic:substeps=1"}), &makeDyingBackend);
  const std::vector<RunGroup::StepFailure> failures =
      stepInParts(group, DyingBackend::kFailingStep);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].label, "elastic:substeps=1");
  ASSERT_EQ(group.runCount(), 1u) << "the only run is kept, with the scene";
  EXPECT_EQ(group.ballCount(), 40u);
  EXPECT_EQ(group.steps(), std::uint64_t(DyingBackend::kFailingStep - 1))
      << "back at the state before the failed step";
  EXPECT_TRUE(group.paused());
  // On a new backend of its spec: it steps again.
  group.setPaused(false);
  EXPECT_TRUE(stepInParts(group, 3).empty());
  EXPECT_EQ(group.steps(), std::uint64_t(DyingBackend::kFailingStep + 2));
}

TEST(RunGroup, AFailedStepOnOneThreadIsAnErrorInTheSingleThreadedStep) {
  // RunGroup::step() and Simulation::step(), as fooball-cli runs them: the backend's line.
  RunGroup group(gas(40), specsOf({"elastic:substeps=1"}), &makeDyingBackend);
  for (int i = 1; i < DyingBackend::kFailingStep; ++i)
    group.step();
  try {
    group.step();
    ADD_FAILURE() << "the failed step went unreported";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "dying: the engine's process died");
  }
  EXPECT_EQ(group.ballCount(), 40u) << "the state is still there to save";
}

// --- real-time driving -------------------------------------------------------------------------

TEST(RunGroup, TakeDueStepsAccumulatesFractionalFrames) {
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  // 0.7 of a step per frame: the accumulator holds 0.7, 1.4 → 1 step, 1.1 → 1 step, 0.8.
  EXPECT_EQ(group.takeDueSteps(0.7 * kDt, 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(0.7 * kDt, 1.0), 1);
  EXPECT_EQ(group.takeDueSteps(0.7 * kDt, 1.0), 1);
  EXPECT_EQ(group.takeDueSteps(0.7 * kDt, 1.0), 0);
  // Time scale: 0.8 left + 1 frame at 2.5× = 3.3 steps.
  EXPECT_EQ(group.takeDueSteps(kDt, 2.5), 3);
  // 0.3 left + a frame at 0.5× = 0.8: nothing yet.
  EXPECT_EQ(group.takeDueSteps(kDt, 0.5), 0);
  EXPECT_EQ(group.steps(), 0u) << "the caller runs the steps, not takeDueSteps";
}

TEST(RunGroup, PendingTimeIsTheSimulatedTimeNotYetStepped) {
  // pendingTime after takeDueSteps is what was there, plus elapsed·scale, minus steps·dt: the
  // same operations as the definition, so equal to the last bit.
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  EXPECT_EQ(group.pendingTime(), 0.0);
  double expected = 0.0;
  const struct {
    double elapsed;  // s of real time
    double scale;    // simulated s per real s
  } frames[] = {{kDt, 0.05}, {kDt, 0.05}, {0.7 * kDt, 1.0}, {kDt, 1.0}, {kDt, 2.5}, {0.013, 0.3}};
  for (const auto& frame : frames) {
    const double before = group.pendingTime();
    const int steps = group.takeDueSteps(frame.elapsed, frame.scale);
    expected = before + frame.elapsed * frame.scale - steps * group.dt();
    EXPECT_EQ(group.pendingTime(), expected) << frame.elapsed << " s at " << frame.scale << "×";
    EXPECT_GE(group.pendingTime(), 0.0);
    EXPECT_LT(group.pendingTime(), group.dt());
  }
  // At 0.05× a frame of 1/60 s holds a twentieth of a step: nothing due, all of it pending.
  RunGroup slow = groupOf(threeBalls(), {"elastic"});
  EXPECT_EQ(slow.takeDueSteps(kDt, 0.05), 0);
  EXPECT_EQ(slow.pendingTime(), kDt * 0.05);
  // Pausing forgets it, and nothing accumulates while paused; a dropped backlog leaves none.
  slow.setPaused(true);
  EXPECT_EQ(slow.pendingTime(), 0.0);
  EXPECT_EQ(slow.takeDueSteps(kDt, 1.0), 0);
  EXPECT_EQ(slow.pendingTime(), 0.0);
  slow.setPaused(false);
  EXPECT_EQ(slow.takeDueSteps(10.5 * kDt, 1.0),
            static_cast<int>(RunGroup::kMaxStepsPerFramePerTimeScale));
  EXPECT_EQ(slow.pendingTime(), 0.0);
}

TEST(RunGroup, TakeStepsForHoldsEverySimulatedSecondWithoutCapOrDrop) {
  // A recording's frames: 25 frames/s at dt = 1/60 s is 2.4 steps a frame, so the frames take
  // 2, 3, 2, 3, 2 steps: 12 in five frames, exactly 0.2 s, never capped (50 steps at once are
  // 50) and never dropped however dear a step.
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  int steps = 0;
  for (int frame = 0; frame < 5; ++frame)
    steps += group.takeStepsFor(1.0 / 25.0);
  EXPECT_EQ(steps, 12);
  EXPECT_NEAR(group.pendingTime(), 0.0, 1e-12);
  EXPECT_EQ(group.takeStepsFor(50.0 * kDt), 50);
  // Slow motion: a frame at 60 frames/s and 0.25× holds a quarter of a step, drawn ahead.
  EXPECT_EQ(group.takeStepsFor(0.25 * kDt), 0);
  EXPECT_NEAR(group.pendingTime(), 0.25 * kDt, 1e-15);
  EXPECT_EQ(group.takeStepsFor(0.75 * kDt), 1);
  // Paused: nothing, and nothing kept.
  group.setPaused(true);
  EXPECT_EQ(group.takeStepsFor(kDt), 0);
  EXPECT_EQ(group.pendingTime(), 0.0);
  EXPECT_EQ(group.steps(), 0u) << "the caller runs the steps, not takeStepsFor";
}

TEST(RunGroup, TakeDueStepsCapsAndDropsTheBacklog) {
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  // A 10.5-step stall at time scale 1 is capped at 4 steps now; the other 6.5 are dropped.
  const int cap = static_cast<int>(RunGroup::kMaxStepsPerFramePerTimeScale);
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0), cap);
  EXPECT_EQ(group.takeDueSteps(0.6 * kDt, 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(0.6 * kDt, 1.0), 1);
  // The cap grows with the time scale (4 · 2.5 = 10), and is at least one step.
  EXPECT_EQ(group.takeDueSteps(100.0 * kDt, 2.5), 10);
  EXPECT_EQ(group.takeDueSteps(100.0 * kDt, 0.01), 1);
}

TEST(RunGroup, TakeDueStepsTakesNoMoreStepsThanAFrameOfSteppingHolds) {
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  const double frame = RunGroup::kSteppingPerFrame;  // s of wall-clock stepping
  // Steps that cost more than a frame: one a frame, whatever is due; the rest is dropped.
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, 1.5 * frame), 1);
  EXPECT_EQ(group.pendingTime(), 0.0);
  // Three fit in a frame at 0.3 of one; then the time-scale cap (4) rules, and so it does for
  // an unknown cost (0) or a nonsense one.
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, 0.3 * frame), 3);
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, 0.01 * frame), 4);
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, 0.0), 4);
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, -1.0), 4);
  EXPECT_EQ(group.takeDueSteps(10.5 * kDt, 1.0, std::nan("")), 4);
  // A machine that keeps up at one dear step a frame keeps real time: the fraction of a step
  // not due yet stays banked.
  RunGroup steady = groupOf(threeBalls(), {"elastic"});
  int steps = 0;
  for (int i = 0; i < 100; ++i)
    steps += steady.takeDueSteps(kDt, 1.0, 0.9 * frame);
  EXPECT_GE(steps, 99);
  EXPECT_LE(steps, 100);
}

TEST(RunGroup, TakeDueStepsKeepsRealTimeWhenTheCapIsNotExceeded) {
  // Frames of 3.8 steps with a cap of 4 per frame: the machine keeps up, so simulated time must
  // follow real time (380 steps in 100 frames, give or take the one step still accumulating).
  // Only a backlog beyond the cap may be dropped, never the fraction of a step not due yet.
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  int steps = 0;
  for (int frame = 0; frame < 100; ++frame)
    steps += group.takeDueSteps(3.8 * kDt, 1.0);
  EXPECT_GE(steps, 379);
  EXPECT_LE(steps, 380);
}

TEST(RunGroup, TakeDueStepsTakesNoneWhilePausedAndOwesNoneAfterwards) {
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  EXPECT_EQ(group.takeDueSteps(0.9 * kDt, 1.0), 0);  // 0.9 banked…
  group.setPaused(true);
  EXPECT_TRUE(group.paused());
  EXPECT_EQ(group.takeDueSteps(1.0, 1.0), 0);
  // Single steps still work while paused.
  group.step();
  EXPECT_EQ(group.steps(), 1u);
  group.setPaused(false);
  // …and forgotten: neither the paused second nor the banked 0.9 is owed.
  EXPECT_EQ(group.takeDueSteps(0.5 * kDt, 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(0.6 * kDt, 1.0), 1);
}

TEST(RunGroup, TakeDueStepsIgnoresNegativeAndNonFiniteElapsedTimes) {
  // A clock that steps back must not bank a debt that swallows the next frames.
  RunGroup group = groupOf(threeBalls(), {"elastic"});
  EXPECT_EQ(group.takeDueSteps(-1.0, 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(std::numeric_limits<double>::quiet_NaN(), 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(std::numeric_limits<double>::infinity(), 1.0), 0);
  EXPECT_EQ(group.takeDueSteps(1.2 * kDt, 1.0), 1);
  group.takeDueSteps(0.5 * kDt, 1.0);
  group.dropBacklog();
  EXPECT_EQ(group.takeDueSteps(0.6 * kDt, 1.0), 0) << "the 0.7 left was dropped";
}

}  // namespace
}  // namespace fooball
