// Mouse tools and attractors. Forces are closed-form (springs F = m·strength·(c − x), one
// launch impulse), computed by a few multiplications, so they are checked to 1e-12 relative.
// Where the tool's effect needs time integration (grab), a Simulation with the elastic backend
// runs it.

#include "fooball/interactions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;

using testing::kDt;
using testing::kRounding;

/// Balls as a test builds them; view() is what the interactions see.
struct TestBalls {
  std::vector<Vec2> positions, velocities;
  std::vector<double> radii, masses;

  void add(Vec2 position, double mass, Vec2 velocity = {}) {
    positions.push_back(position);
    velocities.push_back(velocity);
    radii.push_back(0.2);
    masses.push_back(mass);
  }
  BallsView view() const { return {positions, velocities, radii, masses}; }
  std::size_t size() const { return positions.size(); }
};

/// Three balls of different masses, spread over the box.
TestBalls threeBalls() {
  TestBalls balls;
  balls.add({2.0, 2.0}, 1.0, {0.5, -1.0});
  balls.add({8.0, 5.0}, 3.0, {-2.0, 0.25});
  balls.add({13.0, 1.0}, 0.5, {0.0, 3.0});
  return balls;
}

/// The forces for one step, into a buffer prefilled with junk (forces() must overwrite it).
std::vector<Vec2> forcesOf(Interactions& tools, const TestBalls& balls, double dt = kDt) {
  std::vector<Vec2> forces(balls.size(), Vec2{123.0, -456.0});
  tools.forces(balls.view(), dt, forces);
  return forces;
}

void expectNear(Vec2 actual, Vec2 expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

void expectAllZero(const std::vector<Vec2>& forces) {
  for (std::size_t i = 0; i < forces.size(); ++i)
    EXPECT_EQ(forces[i], Vec2{}) << "ball " << i << " got a force";
}

/// m·strength·(c − x): the spring every attract/repel force is (negated for repel).
Vec2 springForce(const TestBalls& balls, std::size_t i, double strength, Vec2 cursor) {
  return balls.masses[i] * strength * (cursor - balls.positions[i]);
}

TEST(Interactions, NoForceWithoutAPressOrAttractors) {
  Interactions tools;
  const TestBalls balls = threeBalls();
  EXPECT_FALSE(tools.active());
  expectAllZero(forcesOf(tools, balls));
}

TEST(Interactions, AttractPullsEveryBallTowardTheCursor) {
  Interactions tools;
  tools.strength = 7.5;
  const TestBalls balls = threeBalls();
  const Vec2 cursor{6.0, 4.0};
  tools.press(cursor, balls.view());
  EXPECT_TRUE(tools.active());
  EXPECT_FALSE(tools.target()) << "scope All acts on every ball, not one";
  const auto forces = forcesOf(tools, balls);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    SCOPED_TRACE(i);
    const Vec2 expected = springForce(balls, i, 7.5, cursor);
    expectNear(forces[i], expected, kRounding * length(expected));
    EXPECT_GT(dot(forces[i], cursor - balls.positions[i]), 0.0) << "toward the cursor";
  }
}

TEST(Interactions, AttractFollowsTheCursorAndStopsOnRelease) {
  Interactions tools;
  const TestBalls balls = threeBalls();
  tools.press({6.0, 4.0}, balls.view());
  const Vec2 moved{10.0, 7.0};
  tools.move(moved);
  EXPECT_EQ(tools.cursor(), moved);
  const auto forces = forcesOf(tools, balls);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Vec2 expected = springForce(balls, i, tools.strength, moved);
    expectNear(forces[i], expected, kRounding * length(expected));
  }
  tools.release(moved);
  EXPECT_FALSE(tools.pressed());
  EXPECT_FALSE(tools.active());
  expectAllZero(forcesOf(tools, balls));
}

TEST(Interactions, RepelPushesEveryBallAwayFromTheCursor) {
  Interactions tools;
  tools.mode = MouseMode::Repel;
  tools.strength = 4.0;
  const TestBalls balls = threeBalls();
  const Vec2 cursor{6.0, 4.0};
  tools.press(cursor, balls.view());
  EXPECT_TRUE(tools.active());
  const auto forces = forcesOf(tools, balls);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    SCOPED_TRACE(i);
    const Vec2 expected = -springForce(balls, i, 4.0, cursor);
    expectNear(forces[i], expected, kRounding * length(expected));
    EXPECT_LT(dot(forces[i], cursor - balls.positions[i]), 0.0) << "away from the cursor";
  }
}

TEST(Interactions, ScopeNearestActsOnlyOnTheBallNearestThePress) {
  Interactions tools;
  tools.scope = Scope::Nearest;
  const TestBalls balls = threeBalls();
  tools.press({7.0, 4.5}, balls.view());  // nearest: ball 1 at (8, 5)
  ASSERT_EQ(tools.target(), 1u);
  // Moving the cursor next to another ball keeps the target taken at the press.
  const Vec2 cursor{2.5, 2.0};
  tools.move(cursor);
  const auto forces = forcesOf(tools, balls);
  EXPECT_EQ(forces[0], Vec2{});
  EXPECT_EQ(forces[2], Vec2{});
  const Vec2 expected = springForce(balls, 1, tools.strength, cursor);
  expectNear(forces[1], expected, kRounding * length(expected));

  tools.mode = MouseMode::Repel;
  tools.press({13.0, 1.5}, balls.view());
  ASSERT_EQ(tools.target(), 2u);
  const auto repelled = forcesOf(tools, balls);
  EXPECT_EQ(repelled[0], Vec2{});
  EXPECT_EQ(repelled[1], Vec2{});
  expectNear(repelled[2], -springForce(balls, 2, tools.strength, {13.0, 1.5}), 1e-12);
}

TEST(Interactions, ScopeSelectedActsOnlyOnTheSelectedBall) {
  Interactions tools;
  tools.scope = Scope::Selected;
  tools.selected = 2;
  const TestBalls balls = threeBalls();
  const Vec2 cursor{7.9, 5.0};  // right next to ball 1; the selection still wins
  tools.press(cursor, balls.view());
  EXPECT_EQ(tools.target(), 2u);
  EXPECT_TRUE(tools.active());
  const auto forces = forcesOf(tools, balls);
  EXPECT_EQ(forces[0], Vec2{});
  EXPECT_EQ(forces[1], Vec2{});
  const Vec2 expected = springForce(balls, 2, tools.strength, cursor);
  expectNear(forces[2], expected, kRounding * length(expected));
}

TEST(Interactions, ScopeSelectedWithNothingSelectedDoesNothing) {
  const TestBalls balls = threeBalls();
  for (const MouseMode mode :
       {MouseMode::Attract, MouseMode::Repel, MouseMode::Grab, MouseMode::Slingshot}) {
    SCOPED_TRACE(static_cast<int>(mode));
    Interactions tools;
    tools.mode = mode;
    tools.scope = Scope::Selected;
    tools.press({8.0, 5.0}, balls.view());
    EXPECT_FALSE(tools.target());
    EXPECT_FALSE(tools.active());
    expectAllZero(forcesOf(tools, balls));
    tools.release({4.0, 4.0});
    EXPECT_FALSE(tools.active());
    expectAllZero(forcesOf(tools, balls));
  }
  // A selection beyond the balls there are is no selection.
  Interactions tools;
  tools.scope = Scope::Selected;
  tools.selected = 3;
  tools.press({8.0, 5.0}, balls.view());
  EXPECT_FALSE(tools.target());
  expectAllZero(forcesOf(tools, balls));
}

TEST(Interactions, GrabActsOnlyOnTheTargetAsACriticallyDampedSpring) {
  // Two probes of the same spring: a ball at rest off the cursor feels m·ω²·(c − x), a ball on
  // the cursor moving at v feels −m·2ζω·v. Critical damping is ζ = 1: the ω of both agree.
  Interactions tools;
  tools.mode = MouseMode::Grab;
  TestBalls balls = threeBalls();
  balls.velocities[1] = {};
  tools.press({8.1, 5.0}, balls.view());
  ASSERT_EQ(tools.target(), 1u);
  EXPECT_TRUE(tools.active());
  const Vec2 cursor{11.0, 7.0};
  tools.move(cursor);
  const auto pull = forcesOf(tools, balls);
  EXPECT_EQ(pull[0], Vec2{});
  EXPECT_EQ(pull[2], Vec2{});
  const Vec2 offset = cursor - balls.positions[1];
  const double stiffness = length(pull[1]) / (balls.masses[1] * length(offset));  // ω², 1/s²
  EXPECT_NEAR(dot(pull[1], offset), length(pull[1]) * length(offset), 1e-9 * length(pull[1]))
      << "the pull points at the cursor";
  const double omega = std::sqrt(stiffness);
  EXPECT_GT(omega * kDt, 0.05) << "a grab that follows the hand within a fraction of a second";
  // Kick-then-drift with this spring diverges beyond ω·dt ≈ 0.84 (spectral radius of the step
  // map > 1), so the grab must stay below that.
  EXPECT_LT(omega * kDt, 0.8) << "an explicit kick this stiff diverges";

  balls.positions[1] = cursor;
  balls.velocities[1] = {1.5, -2.0};
  const auto drag = forcesOf(tools, balls);
  const double dampingRate = length(drag[1]) / (balls.masses[1] * length(balls.velocities[1]));
  EXPECT_NEAR(dot(drag[1], balls.velocities[1]), -length(drag[1]) * 2.5, 1e-9 * length(drag[1]))
      << "the damping opposes the velocity";
  EXPECT_NEAR(dampingRate, 2.0 * omega, 1e-9 * omega) << "critically damped: c = 2ω";
}

TEST(Interactions, GrabTargetsTheSelectedBallUnderScopeSelected) {
  Interactions tools;
  tools.mode = MouseMode::Grab;
  tools.scope = Scope::Selected;
  tools.selected = 0;
  const TestBalls balls = threeBalls();
  tools.press({13.0, 1.0}, balls.view());  // on ball 2, but ball 0 is selected
  EXPECT_EQ(tools.target(), 0u);
  const auto forces = forcesOf(tools, balls);
  EXPECT_NE(forces[0], Vec2{});
  EXPECT_EQ(forces[1], Vec2{});
  EXPECT_EQ(forces[2], Vec2{});
}

/// Grabs ball 0 of `scene` at its centre, drags the cursor to `cursor` and runs `seconds`.
Simulation grabAndHold(const Scene& scene, Vec2 cursor, double dt, double seconds) {
  Simulation simulation(scene, createBackend("elastic"));
  simulation.setDt(dt);
  simulation.interactions.mode = MouseMode::Grab;
  simulation.interactions.press(scene.balls[0].position, simulation.balls());
  simulation.interactions.move(cursor);
  simulation.run(seconds);
  return simulation;
}

TEST(Interactions, GrabDrivesTheBallToTheCursorAndHoldsItThere) {
  Scene scene = emptyBox();
  scene.balls = {ball({4.0, 4.5}, {2.0, -1.0}, 0.3), ball({12.0, 2.0}, {}, 0.3)};
  const Vec2 cursor{10.0, 6.0};
  // A critically damped spring closes a gap d as d·(1 + ωt)·e^{−ωt}: after 1 s that is ~1e-8 m
  // at ω = 25 rad/s and still < 3 mm for any ω ≥ 10 rad/s, so 1 cm is a tight bound for a
  // responsive grab and the ball must be nearly still.
  Simulation simulation = grabAndHold(scene, cursor, kDt, 1.0);
  EXPECT_LT(length(simulation.positions()[0] - cursor), 0.01);
  EXPECT_LT(length(simulation.velocities()[0]), 0.05);
  EXPECT_EQ(simulation.positions()[1], (Vec2{12.0, 2.0})) << "the other ball is not touched";
  // Held: it stays.
  simulation.run(0.5);
  EXPECT_LT(length(simulation.positions()[0] - cursor), 0.01);
  EXPECT_LT(length(simulation.velocities()[0]), 0.05);
}

TEST(Interactions, GrabHoldsTheBallAgainstGravityWithASmallSag) {
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -9.81};
  scene.balls = {ball({4.0, 2.0}, {}, 0.3)};
  const Vec2 cursor{10.0, 6.0};
  // Held by a spring of ω rad/s, the ball hangs g/ω² below the cursor: 1.6 cm at ω = 25. Allow
  // 3 cm ("a few cm"): a grab that sags more than that feels loose.
  Simulation simulation = grabAndHold(scene, cursor, kDt, 1.0);
  EXPECT_LT(length(simulation.positions()[0] - cursor), 0.03);
  simulation.run(0.5);
  EXPECT_LT(length(simulation.positions()[0] - cursor), 0.03);
  EXPECT_LT(simulation.positions()[0].y, cursor.y) << "it hangs below, not above";
}

TEST(Interactions, GrabStaysStableAtACoarseTimeStep) {
  // At dt = 0.1 s an explicit spring of ω = 25 rad/s (ω·dt = 2.5) would diverge; the grab must
  // still bring the ball in. The bound is the same 1 cm as at 60 Hz, after 4 s.
  Scene scene = emptyBox();
  scene.balls = {ball({4.0, 4.5}, {}, 0.3)};
  const Vec2 cursor{10.0, 6.0};
  Simulation simulation = grabAndHold(scene, cursor, 0.1, 4.0);
  EXPECT_LT(length(simulation.positions()[0] - cursor), 0.01);
  EXPECT_LT(length(simulation.velocities()[0]), 0.05);
}

TEST(Interactions, SlingshotGivesNoForceWhileHeldAndOneLaunchOnRelease) {
  Interactions tools;
  tools.mode = MouseMode::Slingshot;
  tools.strength = 6.0;
  const TestBalls balls = threeBalls();
  const Vec2 pressPoint{8.2, 5.1};  // on ball 1
  tools.press(pressPoint, balls.view());
  ASSERT_EQ(tools.target(), 1u);
  tools.move({6.0, 3.0});
  EXPECT_FALSE(tools.active()) << "the ball is only aimed while held";
  expectAllZero(forcesOf(tools, balls));
  const Vec2 releasePoint{5.0, 2.5};
  tools.release(releasePoint);
  EXPECT_TRUE(tools.active());

  // One step's force whose impulse F·dt gives Δv = 0.2·strength·(press − release), away from
  // the pull.
  const double dt = 1.0 / 120.0;
  const auto launch = forcesOf(tools, balls, dt);
  EXPECT_EQ(launch[0], Vec2{});
  EXPECT_EQ(launch[2], Vec2{});
  const Vec2 deltaV = launch[1] * dt / balls.masses[1];
  const Vec2 expected = 0.2 * 6.0 * (pressPoint - releasePoint);
  expectNear(deltaV, expected, kRounding * length(expected));

  // Then nothing: the launch is one step.
  EXPECT_FALSE(tools.active());
  EXPECT_FALSE(tools.target());
  expectAllZero(forcesOf(tools, balls, dt));
}

TEST(Interactions, SlingshotLaunchChangesTheVelocityByExactlyTheLaunchInOneStep) {
  // Through a real backend: the kick contract turns the one step's force into exactly Δv. No
  // gravity, no contact: the elastic backend's free flight keeps the velocity, so the change is
  // exact up to rounding.
  Scene scene = emptyBox();
  scene.balls = {ball({8.0, 4.5}, {0.5, 0.25}, 0.3), ball({2.0, 2.0}, {}, 0.3)};
  Simulation simulation(scene, createBackend("elastic"));
  Interactions& tools = simulation.interactions;
  tools.mode = MouseMode::Slingshot;
  tools.strength = 5.0;
  tools.press({8.0, 4.5}, simulation.balls());
  tools.move({7.0, 4.0});
  simulation.step();
  EXPECT_EQ(simulation.velocities()[0], (Vec2{0.5, 0.25})) << "no force while held";
  tools.release({7.0, 4.0});
  simulation.step();
  const Vec2 expected = Vec2{0.5, 0.25} + 0.2 * 5.0 * Vec2{1.0, 0.5};
  expectNear(simulation.velocities()[0], expected, 1e-12 * length(expected));
  EXPECT_EQ(simulation.velocities()[1], Vec2{});
  simulation.step();
  expectNear(simulation.velocities()[0], expected, 1e-12 * length(expected));
}

TEST(Interactions, SlingshotWithoutBallsLaunchesNothing) {
  Interactions tools;
  tools.mode = MouseMode::Slingshot;
  const TestBalls none;
  tools.press({1.0, 1.0}, none.view());
  EXPECT_FALSE(tools.target());
  tools.release({0.0, 0.0});
  EXPECT_FALSE(tools.active());
  std::vector<Vec2> forces;
  tools.forces(none.view(), kDt, forces);  // must not touch a ball that is not there
}

TEST(Interactions, AttractorsActOnAllBallsWithoutAPress) {
  Interactions tools;
  tools.strength = 3.0;
  const TestBalls balls = threeBalls();
  const Vec2 first{4.0, 4.0};
  const Vec2 second{12.0, 6.0};
  tools.addAttractor(first);
  tools.addAttractor(second);
  ASSERT_EQ(tools.attractors().size(), 2u);
  EXPECT_EQ(tools.attractors()[1], second);
  EXPECT_FALSE(tools.pressed());
  EXPECT_TRUE(tools.active());
  const auto forces = forcesOf(tools, balls);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    SCOPED_TRACE(i);
    const Vec2 expected = springForce(balls, i, 3.0, first) + springForce(balls, i, 3.0, second);
    expectNear(forces[i], expected, kRounding * length(expected));
  }

  // They add to the cursor tool, which keeps its own scope.
  tools.scope = Scope::Nearest;
  const Vec2 cursor{13.0, 1.5};
  tools.press(cursor, balls.view());  // nearest: ball 2
  const auto withTool = forcesOf(tools, balls);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    SCOPED_TRACE(i);
    Vec2 expected = springForce(balls, i, 3.0, first) + springForce(balls, i, 3.0, second);
    if (i == 2) expected += springForce(balls, i, 3.0, cursor);
    expectNear(withTool[i], expected, kRounding * length(expected));
  }

  tools.release(cursor);
  tools.clearAttractors();
  EXPECT_TRUE(tools.attractors().empty());
  EXPECT_FALSE(tools.active());
  expectAllZero(forcesOf(tools, balls));
}

TEST(Interactions, ActiveIsTrueExactlyWhenSomeBallWouldFeelAForce) {
  const TestBalls balls = threeBalls();
  const TestBalls none;
  struct Case {
    const char* what;
    MouseMode mode;
    Scope scope;
    bool withBalls;
    bool active;
  };
  const Case pressedCases[] = {
      {"attract all", MouseMode::Attract, Scope::All, true, true},
      {"repel all", MouseMode::Repel, Scope::All, true, true},
      {"attract nearest", MouseMode::Attract, Scope::Nearest, true, true},
      {"attract nearest, no balls", MouseMode::Attract, Scope::Nearest, false, false},
      {"grab", MouseMode::Grab, Scope::All, true, true},
      {"grab, no balls", MouseMode::Grab, Scope::All, false, false},
      {"slingshot held", MouseMode::Slingshot, Scope::All, true, false},
  };
  for (const Case& c : pressedCases) {
    SCOPED_TRACE(c.what);
    Interactions tools;
    tools.mode = c.mode;
    tools.scope = c.scope;
    const TestBalls& used = c.withBalls ? balls : none;
    tools.press({7.5, 4.5}, used.view());  // near ball 1, not on its centre (zero pull there)
    EXPECT_EQ(tools.active(), c.active);
    // active() is a promise about forces(): false means all zero, true means some non-zero.
    const auto forces = forcesOf(tools, used);
    bool anyForce = false;
    for (const Vec2 f : forces)
      anyForce = anyForce || f != Vec2{};
    if (c.withBalls) {
      EXPECT_EQ(anyForce, c.active);
    }
    tools.release({7.0, 4.0});
    const bool launchPending = c.mode == MouseMode::Slingshot && c.withBalls;
    EXPECT_EQ(tools.active(), launchPending) << "after release";
  }
  Interactions attractorsOnly;
  attractorsOnly.addAttractor({1.0, 1.0});
  EXPECT_TRUE(attractorsOnly.active());
}

TEST(Interactions, ForgetBallsClearsTargetsSelectionAndPendingLaunch) {
  const TestBalls balls = threeBalls();
  Interactions tools;
  tools.mode = MouseMode::Grab;
  tools.selected = 1;
  tools.press({2.0, 2.0}, balls.view());
  ASSERT_TRUE(tools.target());
  tools.forgetBalls();
  EXPECT_FALSE(tools.target());
  EXPECT_FALSE(tools.selected);
  EXPECT_FALSE(tools.active());
  expectAllZero(forcesOf(tools, balls));

  tools.mode = MouseMode::Slingshot;
  tools.press({2.0, 2.0}, balls.view());
  tools.release({1.0, 1.0});
  ASSERT_TRUE(tools.active());
  tools.forgetBalls();
  EXPECT_FALSE(tools.active()) << "a launch for a ball that may be gone is dropped";
  expectAllZero(forcesOf(tools, balls));
}

TEST(Interactions, NearestBallIsTheClosestEdge) {
  const TestBalls balls = threeBalls();
  EXPECT_EQ(nearestBall({7.0, 4.0}, balls.positions, balls.radii), 1u);
  EXPECT_EQ(nearestBall({100.0, -50.0}, balls.positions, balls.radii), 2u);
  EXPECT_EQ(nearestBall({2.0, 2.0}, balls.positions, balls.radii), 0u);
  EXPECT_FALSE(nearestBall({1.0, 1.0}, {}, {}));
}

TEST(Interactions, NearestBallIsTheOneUnderThePointBesideASmallerCloserCentre) {
  // Pressed 1.9 m from a big ball's centre, inside it; a small ball's centre is 1.4 m away.
  const std::vector<Vec2> positions{{5.0, 4.5}, {8.3, 4.5}};
  const std::vector<double> radii{2.0, 0.1};
  EXPECT_EQ(nearestBall({6.9, 4.5}, positions, radii), 0u);
  // Outside both: the nearer edge (0.75 m to the big one's, 1.7 m to the small one's), though
  // the small one's centre is nearer (1.8 m against 2.7 m).
  EXPECT_EQ(nearestBall({7.3, 3.0}, positions, radii), 0u);
  EXPECT_EQ(nearestBall({8.3, 4.0}, positions, radii), 1u);
}

}  // namespace
}  // namespace fooball
