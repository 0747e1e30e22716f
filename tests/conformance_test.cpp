// The contract every registered backend meets (DESIGN.md, "Backend contract"). The suite is
// instantiated over registeredBackends(), so a new backend is tested by its registry line and
// its row in tests/backend_profiles.cpp (its tolerances and why).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "allocation_counter.h"
#include "backend_profiles.h"
#include "backend_state.h"
#include "fooball/metrics.h"
#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;
using testing::gas;

using testing::ConformanceTolerances;

/// How far `backend` may stray from exact answers, and why: its row in tests/backend_profiles.cpp.
const ConformanceTolerances& tolerancesFor(std::string_view backend) {
  return testing::profileFor(backend).conformance;
}

class Conformance : public ::testing::TestWithParam<BackendInfo> {
 protected:
  std::unique_ptr<Backend> make() const { return GetParam().create(); }
  const ConformanceTolerances& tolerances() const { return tolerancesFor(GetParam().name); }
};

using testing::readState;
using testing::State;

std::vector<double> massesOf(const Scene& scene) {
  std::vector<double> masses;
  for (const BallDef& b : scene.balls)
    masses.push_back(b.mass);
  return masses;
}

double momentumScale(const Scene& scene) {
  double scale = 0.0;
  for (const BallDef& b : scene.balls)
    scale += b.mass * length(b.velocity);
  return scale;
}

using testing::runFor;

TEST_P(Conformance, MomentumIsConservedWithWallsOff) {
  Scene scene = gas(300);
  scene.world.walls = {false, false, false, false};
  auto backend = make();
  backend->load(scene);
  const Vec2 before =
      sumState(readState(*backend).positions, readState(*backend).velocities, massesOf(scene), {})
          .momentum;
  runFor(*backend, 3.0);
  const State after = readState(*backend);
  const Vec2 momentum = sumState(after.positions, after.velocities, massesOf(scene), {}).momentum;
  EXPECT_GT(backend->counters().ballCollisions, 50u) << "the test needs collisions to mean much";
  EXPECT_LE(length(momentum - before), tolerances().momentum * momentumScale(scene));
}

TEST_P(Conformance, KineticEnergyIsConservedInAGasWithoutGravity) {
  const Scene scene = gas(300);
  auto backend = make();
  backend->load(scene);
  const double before =
      sumState(readState(*backend).positions, readState(*backend).velocities, massesOf(scene), {})
          .kineticEnergy;
  runFor(*backend, 5.0);
  const State after = readState(*backend);
  const double energy =
      sumState(after.positions, after.velocities, massesOf(scene), {}).kineticEnergy;
  EXPECT_GT(backend->counters().ballCollisions, 100u);
  EXPECT_GT(backend->counters().wallCollisions, 100u);
  EXPECT_NEAR(energy / before, 1.0, tolerances().energy);
}

TEST_P(Conformance, EnergyUnderGravityChangesAsTheProfileSays) {
  // The same gas under gravity: kinetic and potential energy trade at every bounce and in every
  // flight, so a method's flight integrator and its bounces under load show here. A method that
  // keeps the energy does so to rounding; one that gains or loses it has the change pinned both
  // ways (tests/backend_profiles.cpp).
  Scene scene = gas(300);
  scene.world.gravity = {0.0, -9.81};
  auto backend = make();
  backend->load(scene);
  const State start = readState(*backend);
  const double before =
      sumState(start.positions, start.velocities, massesOf(scene), scene.world.gravity)
          .totalEnergy();
  runFor(*backend, 5.0);
  const State after = readState(*backend);
  const double energy =
      sumState(after.positions, after.velocities, massesOf(scene), scene.world.gravity)
          .totalEnergy();
  EXPECT_GT(backend->counters().ballCollisions, 100u);
  EXPECT_GT(backend->counters().wallCollisions, 100u);
  const testing::Interval& pinned = tolerances().energyUnderGravity;
  EXPECT_TRUE(pinned.contains(energy / before - 1.0))
      << "relative change " << energy / before - 1.0 << ", allowed " << pinned.low << " to "
      << pinned.high;
}

TEST_P(Conformance, NobodyEscapesAClosedBoxUnderGravityAtHighSpeed) {
  Scene scene = gas(400, 11);
  scene.world.gravity = {3.0, -30.0};
  for (std::size_t i = 0; i < scene.balls.size(); i += 10)
    scene.balls[i].velocity *= 15.0;
  auto backend = make();
  backend->load(scene);
  for (int frame = 0; frame < 240; ++frame) {
    backend->step(1.0 / 60.0, {});
    const State state = readState(*backend);
    for (std::size_t i = 0; i < state.positions.size(); ++i) {
      const Vec2 p = state.positions[i];
      ASSERT_TRUE(isFinite(p) && isFinite(state.velocities[i])) << "ball " << i;
      ASSERT_TRUE(p.x > 0.0 && p.x < scene.box.width && p.y > 0.0 && p.y < scene.box.height)
          << "ball " << i << " at (" << p.x << ", " << p.y << ") in frame " << frame;
    }
  }
}

TEST_P(Conformance, SameSceneGivesTheSameTrajectory) {
  Scene scene = gas(200, 3);
  scene.world.gravity = {0.0, -9.81};
  scene.world.airResistance = 0.1;
  auto first = make();
  auto second = make();
  first->load(scene);
  second->load(scene);
  runFor(*first, 2.0);
  runFor(*second, 2.0);
  const State a = readState(*first);
  const State b = readState(*second);
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    ASSERT_EQ(a.positions[i], b.positions[i]) << "ball " << i;
    ASSERT_EQ(a.velocities[i], b.velocities[i]) << "ball " << i;
  }
}

TEST_P(Conformance, LoadingTheStateItReportsGivesBackTheSameState) {
  // What switching backend relies on: the scene rebuilt from readState loads into a new backend
  // of the same kind bit for bit (Box2D's float state widens to doubles that are floats again).
  Scene scene = gas(150, 5);
  scene.world.gravity = {0.0, -4.0};
  auto original = make();
  original->load(scene);
  runFor(*original, 1.0);
  const State state = readState(*original);
  ASSERT_EQ(state.positions.size(), scene.balls.size());
  Scene reported = scene;
  for (std::size_t i = 0; i < reported.balls.size(); ++i) {
    reported.balls[i].position = state.positions[i];
    reported.balls[i].velocity = state.velocities[i];
  }
  auto copy = make();
  copy->load(reported);
  const State again = readState(*copy);
  for (std::size_t i = 0; i < state.positions.size(); ++i) {
    ASSERT_EQ(again.positions[i], state.positions[i]) << "ball " << i;
    ASSERT_EQ(again.velocities[i], state.velocities[i]) << "ball " << i;
  }
}

TEST_P(Conformance, SwitchingBackendMidRunKeepsTheState) {
  Scene scene = gas(200, 9);
  scene.world.gravity = {0.0, -9.81};
  for (const BackendInfo& from : registeredBackends()) {
    Simulation simulation(scene, from.create());
    simulation.run(0.5);
    const std::vector<Vec2> positions(simulation.positions().begin(), simulation.positions().end());
    const std::vector<Vec2> velocities(simulation.velocities().begin(),
                                       simulation.velocities().end());
    const auto collisions = simulation.counters().ballCollisions;
    simulation.setBackend(make());
    ASSERT_EQ(simulation.ballCount(), positions.size());
    // The target stores what it can: bit-exact for double backends, nearest float for Box2D.
    const double position = std::max(tolerancesFor(from.name).position, tolerances().position);
    const double velocity = std::max(tolerancesFor(from.name).velocity, tolerances().velocity);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      ASSERT_NEAR(simulation.positions()[i].x, positions[i].x, position) << from.name << " " << i;
      ASSERT_NEAR(simulation.positions()[i].y, positions[i].y, position) << from.name << " " << i;
      const double speed = length(velocities[i]);
      ASSERT_NEAR(simulation.velocities()[i].x, velocities[i].x, velocity * speed) << i;
      ASSERT_NEAR(simulation.velocities()[i].y, velocities[i].y, velocity * speed) << i;
    }
    EXPECT_EQ(simulation.counters().ballCollisions, collisions) << "counters carry over";
    simulation.run(0.5);
    EXPECT_EQ(simulation.metrics().escaped, 0u);
  }
}

TEST_P(Conformance, HeadOnEqualMassesSwapVelocities) {
  Scene scene = emptyBox();
  scene.balls = {ball({5.0, 4.5}, {2.0, 0.0}), ball({11.0, 4.5}, {-1.0, 0.0})};
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 2.0);  // a 5 m gap closing at 3 m/s: contact at t = 5/3 s, no wall before 2 s
  const State state = readState(*backend);
  EXPECT_NEAR(state.velocities[0].x, -1.0, 1.0 * tolerances().velocity);
  EXPECT_NEAR(state.velocities[1].x, 2.0, 2.0 * tolerances().velocity);
  EXPECT_NEAR(state.velocities[0].y, 0.0, 1.0 * tolerances().velocity);
  EXPECT_NEAR(state.velocities[1].y, 0.0, 2.0 * tolerances().velocity);
  EXPECT_EQ(backend->counters().ballCollisions, 1u);
}

TEST_P(Conformance, ForcesActAsAKickAtTheStartOfTheStep) {
  Scene scene = emptyBox();
  scene.balls = {ball({8.0, 4.5}, {1.0, 0.0}, 0.5, 2.0)};
  auto backend = make();
  backend->load(scene);
  const double dt = 0.05;
  const Vec2 force{4.0, -2.0};  // N on a 2 kg ball: Δv = F·dt/m = (0.1, −0.05) m/s
  backend->step(dt, std::vector<Vec2>{force});
  const State state = readState(*backend);
  const Vec2 expectedVelocity{1.1, -0.05};
  const double speed = length(expectedVelocity);
  EXPECT_NEAR(state.velocities[0].x, expectedVelocity.x, speed * tolerances().velocity);
  EXPECT_NEAR(state.velocities[0].y, expectedVelocity.y, speed * tolerances().velocity);
  EXPECT_NEAR(state.positions[0].x, 8.0 + expectedVelocity.x * dt, tolerances().position);
  EXPECT_NEAR(state.positions[0].y, 4.5 + expectedVelocity.y * dt, tolerances().position);
}

TEST_P(Conformance, AWallBounceIsCountedOnceWithItsImpulse) {
  Scene scene = emptyBox();
  scene.balls = {ball({14.0, 4.5}, {3.0, 0.0}, 0.5, 2.0)};
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 1.0);  // reaches the right wall (x = 15.5) after 0.5 s
  const State state = readState(*backend);
  EXPECT_EQ(backend->counters().wallCollisions, 1u);
  EXPECT_NEAR(backend->counters().wallImpulse, 2.0 * 2.0 * 3.0, 12.0 * tolerances().velocity);
  EXPECT_NEAR(state.velocities[0].x, -3.0, 3.0 * tolerances().velocity);
}

TEST_P(Conformance, WallsThatAreOffLetBallsOut) {
  Scene scene = emptyBox();
  scene.world.walls.right = false;
  scene.balls = {ball({14.0, 4.5}, {3.0, 0.0})};
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 2.0);
  EXPECT_NEAR(readState(*backend).positions[0].x, 20.0, tolerances().position);
  EXPECT_EQ(backend->counters().wallCollisions, 0u);
}

TEST_P(Conformance, BallsPassThroughEachOtherWhenCollisionsAreOff) {
  Scene scene = emptyBox();
  scene.world.ballCollisions = false;
  scene.balls = {ball({5.0, 4.5}, {2.0, 0.0}), ball({11.0, 4.5}, {-2.0, 0.0})};
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 2.0);
  const State state = readState(*backend);
  EXPECT_NEAR(state.positions[0].x, 9.0, tolerances().position);
  EXPECT_NEAR(state.positions[1].x, 7.0, tolerances().position);
  EXPECT_EQ(backend->counters().ballCollisions, 0u);
}

TEST_P(Conformance, SetWorldChangesGravityLive) {
  Scene scene = emptyBox();
  scene.balls = {ball({8.0, 4.5}, {0.0, 0.0})};
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 0.5);
  EXPECT_EQ(readState(*backend).velocities[0].y, 0.0);
  scene.world.gravity = {0.0, -2.0};
  backend->setWorld(scene.world);
  runFor(*backend, 0.5);
  EXPECT_NEAR(readState(*backend).velocities[0].y, -1.0, tolerances().velocity);
}

TEST_P(Conformance, SetBallEditsOneBallAndKeepsTheOthers) {
  Scene scene = gas(50, 2);
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 0.25);
  const State before = readState(*backend);
  // Ball 7, smaller (0.05 m: it overlaps nothing new), at rest and heavier, where it is.
  BallDef edited = ball({8.0, 4.5}, {0.0, 0.0}, 0.05, 3.0);
  edited.position = before.positions[7];
  backend->setBall(7, edited);
  const State after = readState(*backend);
  EXPECT_EQ(after.positions[7], before.positions[7]);
  EXPECT_EQ(after.velocities[7], Vec2{});
  EXPECT_EQ(after.positions[8], before.positions[8]);
  EXPECT_EQ(after.velocities[8], before.velocities[8]);
  // The new mass acts: a kick of 3 N for one step on 3 kg gives Δv = F·dt/m = 1/60 m/s, and the
  // ball moves Δv·dt = 1/3600 m along x in that step (forces kick at its start).
  constexpr double kDt = 1.0 / 60.0;
  std::vector<Vec2> forces(scene.balls.size());
  forces[7] = {3.0, 0.0};
  backend->step(kDt, forces);
  const State kicked = readState(*backend);
  EXPECT_NEAR(kicked.velocities[7].x, 1.0 / 60.0, 1.0 / 60.0 * tolerances().velocity);
  EXPECT_NEAR(kicked.velocities[7].y, 0.0, 1.0 / 60.0 * tolerances().velocity);
  const Vec2 moved = kicked.positions[7] - before.positions[7];
  EXPECT_GT(moved.x, 0.5 * kDt / 60.0) << "ball 7 moved";
  EXPECT_NEAR(moved.x, kDt / 60.0, tolerances().position);
  EXPECT_NEAR(moved.y, 0.0, tolerances().position);
}

TEST_P(Conformance, StepsDoNotAllocateInSteadyState) {
  Scene scene = gas(500, 4);
  scene.world.gravity = {0.0, -9.81};
  auto backend = make();
  backend->load(scene);
  std::vector<Vec2> forces(scene.balls.size(), Vec2{0.1, 0.0});
  runFor(*backend, 2.0);  // warm up: buffers grow to their working size
  backend->step(1.0 / 60.0, forces);
  const long before = testing::allocationCount();
  for (int i = 0; i < 60; ++i) {
    backend->step(1.0 / 60.0, i % 2 ? std::span<const Vec2>(forces) : std::span<const Vec2>());
  }
  EXPECT_EQ(testing::allocationCount() - before, 0);
}

TEST_P(Conformance, OptionsHaveValidDefaultsAndRejectNonsense) {
  auto backend = make();
  for (const OptionSpec& spec : backend->options().specs()) {
    EXPECT_GE(spec.defaultValue, spec.min) << spec.name;
    EXPECT_LE(spec.defaultValue, spec.max) << spec.name;
    EXPECT_EQ(backend->options().value(spec.name), spec.defaultValue) << spec.name;
    EXPECT_THROW(backend->setOption(spec.name, spec.max + 1.0), std::invalid_argument);
    EXPECT_THROW(backend->setOption(spec.name, std::nan("")), std::invalid_argument);
  }
  EXPECT_THROW(backend->setOption("no_such_option", 1.0), std::invalid_argument);
}

TEST(BackendProfiles, EveryRowIsARegisteredBackend) {
  for (const testing::BackendProfile& profile : testing::backendProfiles()) {
    const auto backends = registeredBackends();
    EXPECT_TRUE(std::any_of(backends.begin(), backends.end(),
                            [&](const BackendInfo& info) { return info.name == profile.name; }))
        << "tests/backend_profiles.cpp has a row for '" << profile.name
        << "', which is not registered (backends/registry.cpp)";
  }
}

TEST_P(Conformance, HasAProfile) {
  EXPECT_NO_THROW(testing::profileFor(GetParam().name));
}

std::string backendName(const ::testing::TestParamInfo<BackendInfo>& info) {
  return std::string(info.param.name);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, Conformance, ::testing::ValuesIn(registeredBackends()),
                         backendName);

}  // namespace
}  // namespace fooball
