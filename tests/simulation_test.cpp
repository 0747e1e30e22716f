// The Simulation driver with real backends from the registry: time keeping (real-time driving
// is the run group's: run_group_test.cpp), loading, backend switching, ball edits and the energy
// budget. The elastic backend is the reference here because its free flight (with gravity and drag)
// is integrated exactly and its collision impulses conserve energy exactly, so the budget must
// close to rounding; any larger residual is a booking error of the driver, not a method error.

#include "fooball/simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend_state.h"
#include "fooball/metrics.h"
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
using testing::kDt;
using testing::threeBalls;

Simulation elasticSimulation(const Scene& scene) {
  return Simulation(scene, createBackend("elastic"));
}

double totalEnergyOf(const Scene& scene) {
  std::vector<Vec2> positions, velocities;
  std::vector<double> masses;
  for (const BallDef& b : scene.balls) {
    positions.push_back(b.position);
    velocities.push_back(b.velocity);
    masses.push_back(b.mass);
  }
  return sumState(positions, velocities, masses, scene.world.gravity).totalEnergy();
}

void expectSameState(const Simulation& simulation, const std::vector<Vec2>& positions,
                     const std::vector<Vec2>& velocities) {
  ASSERT_EQ(simulation.ballCount(), positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    EXPECT_EQ(simulation.positions()[i], positions[i]) << "ball " << i;
    EXPECT_EQ(simulation.velocities()[i], velocities[i]) << "ball " << i;
  }
}

/// The positions the backend itself reports (readState), not the driver's copy of them.
std::vector<Vec2> backendPositions(const Backend& backend) {
  std::vector<Vec2> positions(backend.ballCount());
  std::vector<Vec2> velocities(backend.ballCount());
  backend.readState(positions, velocities);
  return positions;
}

// --- time ---------------------------------------------------------------------------------

TEST(Simulation, TimeIsAWholeNumberOfStepsTimesDtExactly) {
  Simulation simulation = elasticSimulation(threeBalls());
  EXPECT_EQ(simulation.dt(), kDt);
  EXPECT_EQ(simulation.time(), 0.0);
  for (int i = 0; i < 7; ++i)
    simulation.step();
  simulation.run(0.5);  // 30 steps
  EXPECT_EQ(simulation.steps(), 37u);
  // Exact: 37·dt, not dt summed 37 times (which drifts by a few ulps).
  EXPECT_EQ(simulation.time(), 37.0 * kDt);
  simulation.run(1000.0 * kDt);
  EXPECT_EQ(simulation.time(), 1037.0 * kDt);
}

TEST(Simulation, RunRoundsToWholeSteps) {
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(0.1);  // 6.000000000000001 steps of 1/60 s
  EXPECT_EQ(simulation.steps(), 6u);
  simulation.run(0.4 * kDt);
  EXPECT_EQ(simulation.steps(), 6u);
  simulation.run(0.6 * kDt);
  EXPECT_EQ(simulation.steps(), 7u);
}

TEST(Simulation, ChangingDtMidRunContinuesTimeFromWhereItWas) {
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(10.0 * kDt);
  const double before = simulation.time();
  EXPECT_EQ(before, 10.0 * kDt);
  const double fineDt = 1.0 / 240.0;
  simulation.setDt(fineDt);
  EXPECT_EQ(simulation.dt(), fineDt);
  EXPECT_EQ(simulation.time(), before) << "changing dt does not move time";
  for (int i = 0; i < 25; ++i)
    simulation.step();
  EXPECT_EQ(simulation.time(), before + 25.0 * fineDt);
  EXPECT_EQ(simulation.steps(), 35u);
  simulation.setDt(0.01);
  simulation.run(0.05);
  EXPECT_EQ(simulation.time(), (before + 25.0 * fineDt) + 5.0 * 0.01);
}

TEST(Simulation, ASceneRunsAtItsOwnTimeStepAndReportsIt) {
  Scene scene = threeBalls();
  scene.dt = 0.002;
  Simulation simulation = elasticSimulation(scene);
  EXPECT_EQ(simulation.dt(), 0.002);
  EXPECT_EQ(simulation.scene().dt, std::optional<double>(0.002)) << "saved with the scene";
  simulation.setDt(kDefaultDt);
  EXPECT_FALSE(simulation.scene().dt) << "the default step is not written";
  simulation.load(threeBalls());
  EXPECT_EQ(simulation.dt(), kDefaultDt);
  scene.dt = 0.004;
  simulation.load(scene);
  EXPECT_EQ(simulation.dt(), 0.004) << "a load takes the scene's step";
}

TEST(Simulation, SetDtRejectsNonPositiveAndNonFiniteSteps) {
  Simulation simulation = elasticSimulation(threeBalls());
  for (const double bad : {0.0, -kDt, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(simulation.setDt(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(simulation.dt(), kDt);
}

/// Forwards to a real backend but refuses to step more than `limit` times, so a runaway loop in
/// the driver fails the test at once instead of hanging it.
class StepLimitedBackend final : public testing::ForwardingBackend {
 public:
  StepLimitedBackend(std::unique_ptr<Backend> inner, int limit)
      : ForwardingBackend(std::move(inner)), stepsLeft_(limit) {}
  void step(double dt, std::span<const Vec2> forces) override {
    if (--stepsLeft_ < 0) throw std::runtime_error("runaway: more steps than the test allows");
    ForwardingBackend::step(dt, forces);
  }

 private:
  int stepsLeft_;
};

TEST(Simulation, RunWithANegativeOrNonFiniteDurationRunsNoSteps) {
  // run(−1) must not turn into 2⁶⁴ − 60 steps. Refusing the duration (std::invalid_argument)
  // or running nothing are both fine; the step-limited backend turns a runaway into a failure.
  for (const double seconds : {-1.0, -kDt, std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity()}) {
    SCOPED_TRACE(seconds);
    Simulation simulation(threeBalls(),
                          std::make_unique<StepLimitedBackend>(createBackend("elastic"), 1000));
    try {
      simulation.run(seconds);
    } catch (const std::invalid_argument&) {
    } catch (const std::exception& error) {
      ADD_FAILURE() << error.what();
    }
    EXPECT_EQ(simulation.steps(), 0u);
    EXPECT_EQ(simulation.time(), 0.0);
  }
}

// --- load and backend switching ---------------------------------------------------------------

TEST(Simulation, LoadResetsTimeCountersAndTheEnergyBudget) {
  Scene scene = threeBalls();
  Simulation simulation = elasticSimulation(scene);
  simulation.run(5.0);  // balls reach walls (the first at ~3.7 s)
  ASSERT_GT(simulation.counters().wallCollisions, 0u);
  simulation.setBackend(createBackend("elastic"));  // counters of two backends to forget
  WorldSettings world = simulation.world();
  world.gravity = {0.0, -9.81};
  world.airResistance = 0.3;
  simulation.setWorld(world);
  simulation.run(0.5);
  const Metrics used = simulation.metrics();
  ASSERT_GT(used.wallCollisions, 0u);
  ASSERT_NE(used.externalWork, 0.0);
  ASSERT_GT(used.dragLoss, 0.0);

  scene.balls[0].velocity = {-1.0, 3.0};
  simulation.load(scene);
  EXPECT_EQ(simulation.time(), 0.0);
  EXPECT_EQ(simulation.steps(), 0u);
  const BackendCounters counters = simulation.counters();
  EXPECT_EQ(counters.ballCollisions, 0u);
  EXPECT_EQ(counters.wallCollisions, 0u);
  EXPECT_EQ(counters.wallImpulse, 0.0);
  EXPECT_EQ(counters.dragLoss, 0.0);
  const Metrics fresh = simulation.metrics();
  EXPECT_EQ(fresh.externalWork, 0.0);
  EXPECT_EQ(fresh.energyResidual, 0.0);
  EXPECT_EQ(simulation.world(), scene.world) << "the loaded scene's world, not the edited one";
  EXPECT_EQ(simulation.velocities()[0], (Vec2{-1.0, 3.0}));
  EXPECT_EQ(fresh.sums.totalEnergy(), totalEnergyOf(scene));
}

TEST(Simulation, MetricsCarryTheInitialEnergyTheRelativeErrorDividesBy) {
  // One 2 kg ball at 3 m/s, 1.5 m up under g = 10 m/s²: E(0) = ½·2·3² + 2·10·1.5 = 9 + 30 J.
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -10.0};
  scene.balls = {ball({4.0, 1.5}, {3.0, 0.0}, 0.5, 2.0)};
  Simulation simulation = elasticSimulation(scene);
  EXPECT_EQ(simulation.metrics().initialEnergy, 39.0);
  simulation.run(0.5);
  // An edit is work, booked as such: E(0) stays what the run began with.
  BallDef faster = simulation.scene().balls[0];
  faster.velocity = {5.0, 1.0};
  simulation.setBall(0, faster);
  simulation.run(0.5);
  const Metrics metrics = simulation.metrics();
  EXPECT_EQ(metrics.initialEnergy, 39.0);
  EXPECT_EQ(relativeEnergyError(metrics), metrics.energyResidual / 39.0);
  // A restart begins a new budget, from the energy then.
  const Scene now = simulation.scene();
  simulation.load(now, simulation.time());
  EXPECT_EQ(simulation.metrics().initialEnergy, simulation.metrics().sums.totalEnergy());
  EXPECT_NE(simulation.metrics().initialEnergy, 39.0);
}

TEST(Simulation, LoadAtAStartTimeKeepsTheClockGoingAndStartsTheRestAgain) {
  // A run group that restarts its runs identical mid-run (synchronise) loads them at its time.
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(5.0);
  ASSERT_GT(simulation.counters().wallCollisions, 0u);
  simulation.setDt(0.01);
  const Scene now = simulation.scene();
  simulation.setDt(0.02);
  simulation.load(now, 5.0);
  EXPECT_EQ(simulation.time(), 5.0);
  EXPECT_EQ(simulation.steps(), 0u);
  EXPECT_EQ(simulation.dt(), 0.01) << "the step comes with the state (Scene::dt)";
  EXPECT_EQ(simulation.counters().wallCollisions, 0u);
  EXPECT_EQ(simulation.metrics().time, 5.0);
  EXPECT_EQ(simulation.metrics().energyResidual, 0.0);
  for (std::size_t i = 0; i < now.balls.size(); ++i)
    EXPECT_EQ(simulation.positions()[i], now.balls[i].position) << "ball " << i;
  simulation.step();
  simulation.step();
  EXPECT_EQ(simulation.time(), 5.0 + 2.0 * 0.01) << "start time + steps · dt, exactly";
  simulation.load(now);
  EXPECT_EQ(simulation.time(), 0.0) << "the default start is 0";
}

TEST(Simulation, SetBackendKeepsTheStateAndCountersCarryOver) {
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(5.0);  // the first wall bounces come at ~3.7 s
  const BackendCounters first = simulation.counters();
  ASSERT_GT(first.wallCollisions, 0u);
  const auto positions = copyOf(simulation.positions());
  const auto velocities = copyOf(simulation.velocities());
  const double time = simulation.time();

  simulation.setBackend(createBackend("elastic"));
  expectSameState(simulation, positions, velocities);
  EXPECT_EQ(simulation.time(), time);
  EXPECT_EQ(simulation.steps(), 300u);
  EXPECT_EQ(simulation.counters().wallCollisions, first.wallCollisions)
      << "the new backend starts at zero; the total carries on";
  EXPECT_EQ(simulation.backend().counters().wallCollisions, 0u);

  simulation.run(5.0);
  const BackendCounters second = simulation.backend().counters();
  ASSERT_GT(second.wallCollisions, 0u);
  const BackendCounters total = simulation.counters();
  EXPECT_EQ(total.wallCollisions, first.wallCollisions + second.wallCollisions);
  EXPECT_EQ(total.ballCollisions, first.ballCollisions + second.ballCollisions);
  EXPECT_DOUBLE_EQ(total.wallImpulse, first.wallImpulse + second.wallImpulse);
  EXPECT_EQ(simulation.metrics().wallCollisions, total.wallCollisions);
}

// --- stepping in parts (the GUI steps the backend on a thread of its own) -------------------

TEST(Simulation, AStepInPartsIsTheSameStepAsStep) {
  // The attract tool is on, so the split also carries the forces and books their work.
  Simulation whole = elasticSimulation(gas(40));
  Simulation inParts = elasticSimulation(gas(40));
  for (Simulation* simulation : {&whole, &inParts})
    simulation->interactions.press({8.0, 4.5}, simulation->balls());
  for (int i = 0; i < 60; ++i) {
    whole.step();
    BackendStep step = inParts.beginStep();
    EXPECT_TRUE(inParts.stepping());
    step.run();
    inParts.finishStep(std::move(step));
    EXPECT_FALSE(inParts.stepping());
  }
  expectSameState(inParts, copyOf(whole.positions()), copyOf(whole.velocities()));
  EXPECT_EQ(inParts.time(), whole.time());
  EXPECT_EQ(inParts.metrics().externalWork, whole.metrics().externalWork);
  EXPECT_EQ(inParts.metrics().energyResidual, whole.metrics().energyResidual);
  EXPECT_EQ(inParts.counters().ballCollisions, whole.counters().ballCollisions);
}

TEST(Simulation, WhileAStepIsOutTheStateIsTheOneBeforeIt) {
  Simulation simulation = elasticSimulation(gas(40));
  simulation.run(1.0);
  const auto positions = copyOf(simulation.positions());
  const auto velocities = copyOf(simulation.velocities());
  const Metrics before = simulation.metrics();
  BackendStep step = simulation.beginStep();
  step.run();
  // Finished but not taken back: what the window draws meanwhile.
  expectSameState(simulation, positions, velocities);
  EXPECT_EQ(simulation.time(), before.time);
  EXPECT_EQ(simulation.metrics().ballCollisions, before.ballCollisions);
  simulation.finishStep(std::move(step));
  EXPECT_NE(copyOf(simulation.positions()), positions);
  EXPECT_EQ(simulation.time(), before.time + kDt);
}

TEST(Simulation, AnAbandonedStepLeavesNoTraceAndTheRunGoesOn) {
  Simulation simulation = elasticSimulation(gas(40));
  simulation.interactions.press({8.0, 4.5}, simulation.balls());
  simulation.run(1.0);
  const auto positions = copyOf(simulation.positions());
  const auto velocities = copyOf(simulation.velocities());
  const Metrics before = simulation.metrics();
  ASSERT_GT(before.ballCollisions, 0u);

  BackendStep step = simulation.beginStep();
  step.run();  // it finished, but too late: given up all the same
  simulation.abandonStep(createBackend("elastic"));

  expectSameState(simulation, positions, velocities);
  const Metrics after = simulation.metrics();
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(simulation.steps(), 60u);
  EXPECT_EQ(after.ballCollisions, before.ballCollisions) << "counters carry on, as on a switch";
  EXPECT_EQ(after.wallImpulse, before.wallImpulse);
  EXPECT_EQ(after.externalWork, before.externalWork) << "the abandoned kick is not booked";
  EXPECT_EQ(after.energyResidual, before.energyResidual);

  simulation.run(1.0);  // the new backend steps on, forces and all, and the budget still closes
  EXPECT_EQ(simulation.steps(), 120u);
  EXPECT_LE(std::abs(simulation.metrics().energyResidual),
            1e-9 * std::abs(simulation.metrics().externalWork));
}

TEST(Simulation, SwitchingToAnyRegisteredBackendKeepsTheState) {
  for (const BackendInfo& info : registeredBackends()) {
    SCOPED_TRACE(std::string(info.name));
    Simulation simulation = elasticSimulation(threeBalls());
    simulation.run(0.5);
    const auto positions = copyOf(simulation.positions());
    const auto velocities = copyOf(simulation.velocities());
    simulation.setBackend(info.create());
    EXPECT_EQ(simulation.backend().ballCount(), positions.size());
    // Single-precision backends (Box2D) round the state to float: 16 m · 6e-8 ≈ 1e-6 m.
    for (std::size_t i = 0; i < positions.size(); ++i) {
      EXPECT_NEAR(simulation.positions()[i].x, positions[i].x, 1e-5) << "ball " << i;
      EXPECT_NEAR(simulation.positions()[i].y, positions[i].y, 1e-5) << "ball " << i;
      EXPECT_NEAR(simulation.velocities()[i].x, velocities[i].x, 1e-5) << "ball " << i;
      EXPECT_NEAR(simulation.velocities()[i].y, velocities[i].y, 1e-5) << "ball " << i;
    }
    EXPECT_EQ(simulation.time(), 30.0 * kDt);
  }
}

// --- energy budget ------------------------------------------------------------------------------

TEST(Simulation, ElasticGasWithoutGravityKeepsItsEnergy) {
  // Elastic impulses and wall mirrors conserve kinetic energy exactly in real arithmetic; what
  // is left is rounding: ~1e-16 per operation, a few thousand operations per ball. 1e-9·E is
  // far above that and far below any real loss (one missed collision of 300 changes E by ~0.3%).
  Simulation simulation = elasticSimulation(gas(300));
  const double energy = simulation.metrics().sums.totalEnergy();
  ASSERT_GT(energy, 0.0);
  simulation.run(1.0);
  const Metrics metrics = simulation.metrics();
  ASSERT_GT(metrics.ballCollisions, 0u) << "the test needs collisions to mean something";
  EXPECT_EQ(metrics.externalWork, 0.0);
  EXPECT_EQ(metrics.dragLoss, 0.0);
  EXPECT_LT(std::abs(metrics.energyResidual), 1e-9 * energy);
}

TEST(Simulation, DragLossIsBookedSoTheResidualStaysAtRounding) {
  // The elastic backend integrates drag exactly and reports the energy it removed, so E falls
  // by exactly dragLoss: the residual stays at rounding (same 1e-9·E bound as without drag),
  // while dragLoss grows to a large share of E (c = 0.5/s: KE·(1 − e^{−2ct}) ≈ 63% in 1 s).
  Scene scene = gas(300);
  scene.world.airResistance = 0.5;
  Simulation simulation = elasticSimulation(scene);
  const double energy = simulation.metrics().sums.totalEnergy();
  double previousLoss = 0.0;
  for (int quarter = 0; quarter < 4; ++quarter) {
    simulation.run(0.25);
    const Metrics metrics = simulation.metrics();
    EXPECT_GT(metrics.dragLoss, previousLoss) << "quarter " << quarter;
    previousLoss = metrics.dragLoss;
    EXPECT_LT(std::abs(metrics.energyResidual), 1e-9 * energy) << "quarter " << quarter;
  }
  // Each ball's KE decays as e^{−2ct} between contacts and contacts only exchange KE, so the
  // total decays the same way, exactly: the loss after 1 s is (1 − e^{−1})·E to rounding.
  EXPECT_NEAR(previousLoss / energy, 1.0 - std::exp(-2.0 * 0.5 * 1.0), 1e-9);
}

TEST(Simulation, AttractToolWorkIsBookedExactlyOnASingleBall) {
  // Under the kick contract the driver books J·(v + J/2m) per step, exactly the KE change the
  // kick causes; the elastic free flight (no gravity) keeps v. With no collisions and no walls
  // reached, the residual is rounding only: 1e-12 of the largest work booked. A booking error
  // (e.g. forgetting |J|²/2m) would be O(ω·dt) ≈ 5% of it.
  Scene scene = emptyBox();
  scene.balls = {ball({4.0, 4.5}, {0.0, 1.0}, 0.3)};
  Simulation simulation = elasticSimulation(scene);
  simulation.interactions.press({8.0, 4.5}, simulation.balls());
  double largestWork = 0.0;
  for (int i = 0; i < 30; ++i) {  // half a second: ω = √10 rad/s, the ball swings toward x = 8
    simulation.step();
    const Metrics metrics = simulation.metrics();
    largestWork = std::max(largestWork, std::abs(metrics.externalWork));
    EXPECT_LE(std::abs(metrics.energyResidual), 1e-12 * largestWork) << "step " << i;
  }
  const Metrics metrics = simulation.metrics();
  EXPECT_GT(metrics.externalWork, 1.0) << "the tool did work: ½·m·ω²·d² ≈ 23 J at the cursor";
  EXPECT_EQ(metrics.wallCollisions, 0u);
}

TEST(Simulation, AttractToolOnAGasKeepsTheResidualSmallAgainstTheWork) {
  // With collisions the residual is what the elastic method itself does wrong. Its impulses and
  // position corrections do not change KE, so it is rounding here too; 1e-6 of the work done
  // leaves room for that and still catches any booking error, which is percent-sized.
  Simulation simulation = elasticSimulation(gas(200));
  simulation.interactions.strength = 5.0;
  simulation.interactions.press({8.0, 4.5}, simulation.balls());
  simulation.run(0.5);
  const Metrics metrics = simulation.metrics();
  ASSERT_GT(metrics.ballCollisions, 0u);
  EXPECT_GT(std::abs(metrics.externalWork), 1.0);
  EXPECT_LT(std::abs(metrics.energyResidual), 1e-6 * std::abs(metrics.externalWork));
}

TEST(Simulation, GravityChangeIsBookedAsExternalWork) {
  Scene scene = threeBalls();
  for (BallDef& b : scene.balls)
    b.velocity = {};
  Simulation simulation = elasticSimulation(scene);
  WorldSettings world = simulation.world();
  world.gravity = {0.0, -9.81};
  simulation.setWorld(world);
  EXPECT_EQ(simulation.world(), world);
  // PE jumps from 0 to Σ m·9.81·y, and that jump is work done on the balls by the user.
  double potential = 0.0;
  for (const BallDef& b : scene.balls)
    potential += b.mass * 9.81 * b.position.y;
  Metrics metrics = simulation.metrics();
  EXPECT_NEAR(metrics.externalWork, potential, 1e-12 * potential);
  EXPECT_NEAR(metrics.sums.potentialEnergy, potential, 1e-12 * potential);
  EXPECT_LE(std::abs(metrics.energyResidual), 1e-12 * potential) << "no jump in the residual";

  // Falling freely (no ball reaches the floor in 0.5 s: the lowest falls 1.2 m of 1.7 m), the
  // elastic backend's exact flight keeps the budget at rounding.
  simulation.run(0.5);
  metrics = simulation.metrics();
  EXPECT_EQ(metrics.wallCollisions, 0u);
  EXPECT_GT(metrics.sums.kineticEnergy, 0.1 * potential);
  EXPECT_LE(std::abs(metrics.energyResidual), 1e-9 * potential);

  // Turning gravity off books the opposite jump; drag and walls change no energy.
  world.gravity = {};
  world.airResistance = 0.2;
  world.walls.top = false;
  const double workBefore = simulation.metrics().externalWork;
  const double potentialBefore = simulation.metrics().sums.potentialEnergy;
  simulation.setWorld(world);
  metrics = simulation.metrics();
  EXPECT_NEAR(metrics.externalWork, workBefore - potentialBefore, 1e-12 * potential);
  EXPECT_LE(std::abs(metrics.energyResidual), 1e-9 * potential);
}

TEST(Simulation, SetBallBooksTheEnergyChangeAsExternalWork) {
  Scene scene = threeBalls();
  scene.world.gravity = {0.0, -9.81};
  Simulation simulation = elasticSimulation(scene);
  simulation.run(0.1);
  const Metrics before = simulation.metrics();

  BallDef edited = simulation.scene().balls[1];
  const Vec2 oldVelocity = edited.velocity;
  edited.velocity = {3.0, 4.0};
  simulation.setBall(1, edited);
  EXPECT_EQ(simulation.velocities()[1], (Vec2{3.0, 4.0}));
  const double kineticChange = 0.5 * edited.mass * (25.0 - lengthSquared(oldVelocity));
  Metrics after = simulation.metrics();
  EXPECT_NEAR(after.externalWork - before.externalWork, kineticChange, 1e-12 * 25.0);
  EXPECT_NEAR(after.energyResidual, before.energyResidual, 1e-12 * 25.0);

  // Lifting a ball by 1 m and doubling its mass: the PE and KE changes are booked too.
  const double oldEnergy = after.sums.totalEnergy();
  edited.position.y += 1.0;
  edited.mass *= 2.0;
  simulation.setBall(1, edited);
  EXPECT_EQ(simulation.masses()[1], edited.mass);
  const Metrics lifted = simulation.metrics();
  EXPECT_NEAR(lifted.externalWork - after.externalWork, lifted.sums.totalEnergy() - oldEnergy,
              1e-12 * oldEnergy);
  EXPECT_GT(lifted.externalWork, after.externalWork);
  EXPECT_NEAR(lifted.energyResidual, before.energyResidual, 1e-12 * oldEnergy);
}

TEST(Simulation, SetBallRejectsAnInvalidBallAndLeavesTheStateUnchanged) {
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(0.2);
  const Scene state = simulation.scene();
  const Metrics metrics = simulation.metrics();
  const BallDef good = state.balls[0];
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  struct Case {
    const char* what;
    std::size_t index;
    BallDef ball;
  };
  std::vector<Case> cases;
  const auto add = [&](const char* what, auto edit, std::size_t index = 0) {
    BallDef bad = good;
    edit(bad);
    cases.push_back({what, index, bad});
  };
  add("negative radius", [](BallDef& b) { b.radius = -0.5; });
  add("zero radius", [](BallDef& b) { b.radius = 0.0; });
  add("zero mass", [](BallDef& b) { b.mass = 0.0; });
  add("NaN position", [&](BallDef& b) { b.position.x = kNaN; });
  add("NaN velocity", [&](BallDef& b) { b.velocity.y = kNaN; });
  add("infinite velocity",
      [](BallDef& b) { b.velocity.x = std::numeric_limits<double>::infinity(); });
  add("outside the box", [](BallDef& b) { b.position = {-2.0, 4.5}; });
  add("through the top wall", [](BallDef& b) { b.position = {3.0, 8.9}; });
  add("overlapping another ball", [&](BallDef& b) { b.position = state.balls[2].position; });
  add(
      "no such ball", [](BallDef&) {}, 3);

  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    EXPECT_THROW(simulation.setBall(c.index, c.ball), SceneError);
    const Scene now = simulation.scene();
    ASSERT_EQ(now.balls.size(), state.balls.size());
    for (std::size_t i = 0; i < now.balls.size(); ++i) {
      EXPECT_EQ(now.balls[i].position, state.balls[i].position) << "ball " << i;
      EXPECT_EQ(now.balls[i].velocity, state.balls[i].velocity) << "ball " << i;
      EXPECT_EQ(now.balls[i].radius, state.balls[i].radius) << "ball " << i;
      EXPECT_EQ(now.balls[i].mass, state.balls[i].mass) << "ball " << i;
    }
    EXPECT_EQ(simulation.metrics().externalWork, metrics.externalWork);
    EXPECT_EQ(backendPositions(simulation.backend())[0], state.balls[0].position)
        << "the backend was not touched";
  }

  // Resting against another ball (within the contact slop) is allowed, and so is the ball's
  // own place.
  EXPECT_NO_THROW(simulation.setBall(0, good));
  BallDef touching = good;
  const BallDef& other = state.balls[2];
  touching.position = other.position - Vec2{other.radius + good.radius, 0.0};
  EXPECT_NO_THROW(simulation.setBall(0, touching));
}

TEST(Simulation, SetBallAllowsOverlapWhileBallCollisionsAreOff) {
  // With collisions off balls pass through each other, and the scene rules allow overlap then
  // (validateScene checks it only while ball_collisions is on). Editing a ball that is passing
  // through another (here: just changing its velocity) must work as it does for a saved scene.
  Scene scene = threeBalls();
  scene.world.ballCollisions = false;
  scene.balls[0].position = {11.7, 6.0};  // half inside ball 2 at (12, 6)
  validateScene(scene, "test");           // a valid scene...
  Simulation simulation = elasticSimulation(scene);
  BallDef edited = simulation.scene().balls[0];
  edited.velocity = {0.0, 0.0};
  EXPECT_NO_THROW(simulation.setBall(0, edited));  // ...so a valid edit
  EXPECT_EQ(simulation.velocities()[0], Vec2{});
}

TEST(Simulation, ReplaceBallsKeepsTimeCountersAndBooksTheEnergyChange) {
  Simulation simulation = elasticSimulation(threeBalls());
  simulation.run(5.0);
  const BackendCounters counters = simulation.counters();
  ASSERT_GT(counters.wallCollisions, 0u);
  const Metrics before = simulation.metrics();
  simulation.interactions.scope = Scope::Nearest;
  simulation.interactions.press(simulation.positions()[2], simulation.balls());
  ASSERT_TRUE(simulation.interactions.target());

  std::vector<BallDef> balls = simulation.scene().balls;
  balls.pop_back();
  balls.push_back(ball({14.0, 1.0}, {-3.0, 0.0}, 0.25));
  const double removed = 0.5 * simulation.masses()[2] * lengthSquared(simulation.velocities()[2]);
  const double added = 0.5 * balls.back().mass * 9.0;
  simulation.replaceBalls(balls);

  EXPECT_EQ(simulation.ballCount(), 3u);
  EXPECT_EQ(simulation.time(), 300.0 * kDt);
  EXPECT_EQ(simulation.steps(), 300u);
  EXPECT_EQ(simulation.counters().wallCollisions, counters.wallCollisions);
  EXPECT_EQ(simulation.positions()[2], (Vec2{14.0, 1.0}));
  EXPECT_FALSE(simulation.interactions.target()) << "the old target may be gone";
  const Metrics after = simulation.metrics();
  const double scale = before.sums.totalEnergy();
  EXPECT_NEAR(after.externalWork - before.externalWork, added - removed, 1e-12 * scale);
  EXPECT_NEAR(after.energyResidual, before.energyResidual, 1e-12 * scale);
}

// --- state and metrics ---------------------------------------------------------------------------

TEST(Simulation, SceneReturnsTheCurrentStateWithColoursAndMasses) {
  const Scene original = threeBalls();
  Simulation simulation = elasticSimulation(original);
  simulation.run(1.0);
  const Scene now = simulation.scene();
  EXPECT_EQ(now.name, original.name);
  EXPECT_EQ(now.box, original.box);
  EXPECT_EQ(now.world, original.world);
  ASSERT_EQ(now.balls.size(), original.balls.size());
  for (std::size_t i = 0; i < now.balls.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(now.balls[i].position, simulation.positions()[i]);
    EXPECT_EQ(now.balls[i].velocity, simulation.velocities()[i]);
    EXPECT_NE(now.balls[i].position, original.balls[i].position) << "it is the state now";
    EXPECT_EQ(now.balls[i].radius, original.balls[i].radius);
    EXPECT_EQ(now.balls[i].mass, original.balls[i].mass);
    EXPECT_EQ(now.balls[i].color, original.balls[i].color);
  }
  // And it is the state the backend itself reports.
  const std::vector<Vec2> reported = backendPositions(simulation.backend());
  for (std::size_t i = 0; i < now.balls.size(); ++i)
    EXPECT_EQ(reported[i], now.balls[i].position);
}

TEST(Simulation, MetricsAgreeWithTheMetricFunctionsAndCounters) {
  Scene scene = gas(200);
  scene.world.gravity = {0.0, -9.81};
  scene.world.airResistance = 0.1;
  scene.world.walls.top = false;
  Simulation simulation = elasticSimulation(scene);
  simulation.run(1.0);
  const Metrics metrics = simulation.metrics();
  const StateSums sums = sumState(simulation.positions(), simulation.velocities(),
                                  simulation.masses(), scene.world.gravity);
  EXPECT_EQ(metrics.time, simulation.time());
  EXPECT_EQ(metrics.sums.kineticEnergy, sums.kineticEnergy);
  EXPECT_EQ(metrics.sums.potentialEnergy, sums.potentialEnergy);
  EXPECT_EQ(metrics.sums.momentum, sums.momentum);
  EXPECT_EQ(metrics.sums.centreOfMass, sums.centreOfMass);
  EXPECT_EQ(metrics.maxOverlap, maxOverlap(simulation.positions(), simulation.radii(),
                                           simulation.box(), scene.world.walls));
  EXPECT_EQ(metrics.escaped, countEscaped(simulation.positions(), simulation.box()));
  const BackendCounters counters = simulation.counters();
  EXPECT_EQ(metrics.ballCollisions, counters.ballCollisions);
  EXPECT_EQ(metrics.wallCollisions, counters.wallCollisions);
  EXPECT_EQ(metrics.wallImpulse, counters.wallImpulse);
  EXPECT_EQ(metrics.dragLoss, counters.dragLoss);
  EXPECT_GT(metrics.ballCollisions, 0u);
  EXPECT_GT(metrics.wallCollisions, 0u);
  EXPECT_GT(metrics.dragLoss, 0.0);
  const double initialEnergy = totalEnergyOf(scene);
  EXPECT_NEAR(metrics.energyResidual,
              metrics.sums.totalEnergy() - initialEnergy - metrics.externalWork + metrics.dragLoss,
              1e-12 * initialEnergy);
}

TEST(Simulation, MetricsWithoutGeometryChecksAreTheSameButForOverlapAndEscaped) {
  // Balls pass through each other (collisions off), and the top wall is off: ball 0 moves half
  // inside ball 2 and ball 1 flies out through the top, so both checks have something to find.
  Scene scene = threeBalls();
  scene.world.ballCollisions = false;
  scene.world.walls.top = false;
  scene.balls[0].position = {11.7, 6.0};              // half inside ball 2 at (12, 6)...
  scene.balls[0].velocity = scene.balls[2].velocity;  // ...and staying there
  scene.balls[1].velocity = {0.0, 40.0};
  Simulation simulation = elasticSimulation(scene);
  simulation.run(0.5);
  const Metrics full = simulation.metrics();
  ASSERT_GT(full.maxOverlap, 0.0);
  ASSERT_GT(full.escaped, 0u);
  const Metrics cheap = simulation.metrics(GeometryChecks::Skip);
  EXPECT_EQ(cheap.maxOverlap, 0.0);
  EXPECT_EQ(cheap.escaped, 0u);
  EXPECT_EQ(cheap.time, full.time);
  EXPECT_EQ(cheap.sums.totalEnergy(), full.sums.totalEnergy());
  EXPECT_EQ(cheap.sums.momentum, full.sums.momentum);
  EXPECT_EQ(cheap.ballCollisions, full.ballCollisions);
  EXPECT_EQ(cheap.wallCollisions, full.wallCollisions);
  EXPECT_EQ(cheap.energyResidual, full.energyResidual);
}

}  // namespace
}  // namespace fooball
