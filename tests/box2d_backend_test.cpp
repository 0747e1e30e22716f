#include "box2d/box2d_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backend_state.h"

// Box2D's state is float: positions and velocities carry ~6e-8 relative rounding per operation,
// so a velocity of a few m/s that went through a handful of solver operations is good to ~1e-6
// relative, and tolerances below are stated from that. Collisions are solved when balls already
// overlap (discrete detection at the start of a Box2D step of h seconds), so positions after a
// bounce are ahead of the exact ones by up to 2·v·h; Box2D leaves overlaps up to its linear slop
// (5 mm) uncorrected.

namespace fooball {
namespace {

BallDef ball(Vec2 position, Vec2 velocity, double radius = 0.5, double mass = 1.0) {
  return {position, velocity, radius, mass, 0xe0a030};
}

Scene boxScene(double width, double height, std::vector<BallDef> balls) {
  Scene scene;
  scene.name = "box2d test";
  scene.box = {width, height};
  scene.balls = std::move(balls);
  return scene;
}

/// A box far larger than the test's paths, walls off: free flight.
Scene openSpace(std::vector<BallDef> balls) {
  Scene scene = boxScene(2000.0, 1000.0, std::move(balls));
  scene.world.walls = {false, false, false, false};
  return scene;
}

using Options = std::vector<std::pair<std::string_view, double>>;

std::unique_ptr<Backend> loaded(const Scene& scene, const Options& options = {}) {
  std::unique_ptr<Backend> backend = makeBox2dBackend();
  for (const auto& [name, value] : options)
    backend->setOption(name, value);
  backend->load(scene);
  return backend;
}

void run(Backend& backend, double dt, int steps) {
  for (int i = 0; i < steps; ++i)
    backend.step(dt, {});
}

Vec2 velocityOf(const Backend& backend, std::size_t index) {
  return testing::readState(backend).velocities.at(index);
}

Vec2 positionOf(const Backend& backend, std::size_t index) {
  return testing::readState(backend).positions.at(index);
}

/// J, of the balls of `scene` (the masses) as `backend` now moves them.
double kineticEnergy(const Backend& backend, const Scene& scene) {
  const std::vector<Vec2> velocities = testing::readState(backend).velocities;
  double energy = 0.0;
  for (std::size_t i = 0; i < velocities.size(); ++i)
    energy += 0.5 * scene.balls[i].mass * lengthSquared(velocities[i]);
  return energy;
}

double diagnostic(const Backend& backend, std::string_view name) {
  for (const Diagnostic& d : backend.diagnostics()) {
    if (d.name == name) return d.value;
  }
  ADD_FAILURE() << "no diagnostic named " << name;
  return 0.0;
}

TEST(Box2dBackend, HeadOnEqualMassesSwapVelocities) {
  auto backend =
      loaded(boxScene(16.0, 9.0, {ball({6.0, 4.5}, {2.0, 0.0}), ball({10.0, 4.5}, {-2.0, 0.0})}));
  run(*backend, 1.0 / 240.0, 240);  // they meet at t = 0.75 s

  // One velocity iteration solves a single contact exactly; what is left is float rounding of
  // ±2 m/s through a few operations (< 1e-6 each).
  EXPECT_NEAR(velocityOf(*backend, 0).x, -2.0, 1e-5);
  EXPECT_NEAR(velocityOf(*backend, 1).x, 2.0, 1e-5);
  EXPECT_EQ(velocityOf(*backend, 0).y, 0.0);
  EXPECT_EQ(backend->counters().ballCollisions, 1u);
}

TEST(Box2dBackend, SlowHitBetweenBallsIsStillElastic) {
  // 0.1 m/s is far below Box2D's default restitution threshold of 1 m/s, which would make this
  // hit perfectly inelastic (both balls leaving at 0.05 m/s).
  auto backend =
      loaded(boxScene(16.0, 9.0, {ball({6.0, 4.5}, {0.1, 0.0}), ball({7.5, 4.5}, {0.0, 0.0})}));
  run(*backend, 1.0 / 60.0, 360);  // they meet at t = 5 s

  // 1e-6 m/s: float rounding on 0.1 m/s (ulp ~7e-9) through a few operations, far from 0.05.
  EXPECT_NEAR(velocityOf(*backend, 0).x, 0.0, 1e-6);
  EXPECT_NEAR(velocityOf(*backend, 1).x, 0.1, 1e-6);
}

TEST(Box2dBackend, SlowHitOnAWallIsStillElastic) {
  auto backend = loaded(boxScene(16.0, 9.0, {ball({15.4, 4.5}, {0.1, 0.0})}));
  run(*backend, 1.0 / 60.0, 120);  // reaches the wall at t = 1 s

  EXPECT_NEAR(velocityOf(*backend, 0).x, -0.1, 1e-6);
  EXPECT_EQ(backend->counters().wallCollisions, 1u);
}

TEST(Box2dBackend, BallReflectsOffAWallAtTheBoxEdgeWithItsSpeedKept) {
  const double speed = 3.0;            // m/s
  const double box2dStep = 1.0 / 960;  // s, dt 1/240 with the default 4 substeps
  auto backend = loaded(boxScene(16.0, 9.0, {ball({13.0, 4.5}, {speed, 0.0})}));
  run(*backend, 1.0 / 240.0, 240);  // touches the right wall (x = 15.5) at t = 5/6 s

  EXPECT_NEAR(velocityOf(*backend, 0).x, -speed, 1e-5);
  EXPECT_EQ(velocityOf(*backend, 0).y, 0.0);
  // Exact: reflected at x = 15.5, back at 15.0 at t = 1 s. Box2D reflects up to one step late,
  // from an overlap δ ≤ v·h, which puts the ball 2δ ahead: x ∈ [15, 15 + 2vh]. 5e-4 m more for
  // float rounding of x ≈ 15 (ulp 1e-6) over 960 additions. A wall surface 1 cm inside the box
  // (Box2D's polygon skin, uncompensated) would give x ≈ 14.98.
  EXPECT_NEAR(positionOf(*backend, 0).x, 15.0 + speed * box2dStep, speed * box2dStep + 5e-4);
}

TEST(Box2dBackend, GlancingWallHitKeepsTangentialVelocity) {
  // Box2D's default friction 0.2 would take up to 0.2 × the 2 N·s normal impulse from the
  // tangential momentum: vx would drop to 1.6 m/s.
  auto backend = loaded(boxScene(16.0, 9.0, {ball({8.0, 1.5}, {2.0, -1.0})}));
  run(*backend, 1.0 / 240.0, 360);  // touches the floor at t = 1 s

  EXPECT_NEAR(velocityOf(*backend, 0).x, 2.0, 1e-5);
  EXPECT_NEAR(velocityOf(*backend, 0).y, 1.0, 1e-5);
}

TEST(Box2dBackend, GlancingBallHitLeavesEqualMassesAtRightAngles) {
  // Frictionless elastic equal masses, one at rest: the impulse lies along the line of centres,
  // so the struck ball leaves along it and the striker keeps only its tangential velocity — the
  // two velocities end perpendicular and kinetic energy is kept. Friction (or energy going into
  // spin) would break both.
  const Scene scene =
      boxScene(16.0, 9.0, {ball({4.0, 4.5}, {2.0, 0.0}), ball({8.0, 4.75}, {0.0, 0.0})});
  auto backend = loaded(scene);
  run(*backend, 1.0 / 240.0, 480);  // they meet at t ≈ 1.5 s; no wall is reached by t = 2 s

  const Vec2 striker = velocityOf(*backend, 0);
  const Vec2 struck = velocityOf(*backend, 1);
  ASSERT_EQ(backend->counters().ballCollisions, 1u);
  EXPECT_GT(length(struck), 1.0);
  EXPECT_NEAR(dot(striker, struck), 0.0, 1e-5);            // m²/s², velocities of ~2 m/s to 1e-6
  EXPECT_NEAR(kineticEnergy(*backend, scene), 2.0, 1e-5);  // J, ½ · 1 kg · (2 m/s)²
  EXPECT_NEAR(striker.x + struck.x, 2.0, 1e-5);
  EXPECT_NEAR(striker.y + struck.y, 0.0, 1e-5);
}

TEST(Box2dBackend, FastBallKeepsItsEnergyWhenAutoSubstepsAvoidTheTranslationCap) {
  // 300 m/s at dt = 1/60 is 5 m per step; Box2D caps a body at 2 m per Box2D step.
  auto backend = loaded(openSpace({ball({100.0, 5.0}, {300.0, 0.0})}), {{"substeps", 1.0}});
  run(*backend, 1.0 / 60.0, 10);

  // Nothing acts on the ball: 300 is exact in float and must stay so.
  EXPECT_EQ(velocityOf(*backend, 0).x, 300.0);
  EXPECT_NEAR(positionOf(*backend, 0).x, 150.0, 1e-3);  // float sum of ≥ 30 steps near 150
  EXPECT_EQ(diagnostic(*backend, "translation_cap_hits"), 0.0);
  EXPECT_EQ(diagnostic(*backend, "auto_substeps_raised"), 10.0);
  EXPECT_GE(diagnostic(*backend, "box2d_steps"), 30.0);  // ≥ 3 Box2D steps of ≤ 2 m per step
}

TEST(Box2dBackend, AStopRequestEndsAStepBetweenItsBox2dSteps) {
  // The GUI asks a step it has given up on to stop; with auto_substeps this one would take
  // 3,000 / 2 = 1,500 Box2D steps, capped at 1,000.
  auto backend = loaded(openSpace({ball({100.0, 5.0}, {180'000.0, 0.0})}), {{"substeps", 1.0}});
  backend->step(1.0 / 60.0, {});
  EXPECT_EQ(diagnostic(*backend, "box2d_steps"), 1000.0);
  backend->requestStop();
  backend->step(1.0 / 60.0, {});
  EXPECT_EQ(diagnostic(*backend, "box2d_steps"), 1000.0) << "no Box2D step after the request";
}

TEST(Box2dBackend, TranslationCapSilentlySlowsAFastBallAndIsReported) {
  // Pins the trap the adapter works around: one Box2D step of 1/60 s may move a body 2 m, so
  // Box2D scales 300 m/s down to 120 m/s and 84 % of the kinetic energy disappears.
  const Scene scene = openSpace({ball({100.0, 5.0}, {300.0, 0.0})});
  auto backend = loaded(scene, {{"substeps", 1.0}, {"auto_substeps", 0.0}});
  const double initialEnergy = kineticEnergy(*backend, scene);
  run(*backend, 1.0 / 60.0, 10);

  EXPECT_NEAR(velocityOf(*backend, 0).x, 120.0, 1e-3);
  EXPECT_NEAR(kineticEnergy(*backend, scene) / initialEnergy, 0.16, 1e-5);
  EXPECT_GE(diagnostic(*backend, "translation_cap_hits"), 1.0);
  EXPECT_EQ(diagnostic(*backend, "auto_substeps_raised"), 0.0);
}

/// A heavy ball (100 kg) and a light one (1 kg), radius 2 m, closing head-on at 100 m/s each.
/// The light one leaves at (99·100 + 200·100)/101 ≈ 296 m/s, the heavy one at ≈ 96 m/s.
Scene heavyStrikesLight() {
  return openSpace({ball({100.0, 500.0}, {100.0, 0.0}, 2.0, 100.0),
                    ball({110.0, 500.0}, {-100.0, 0.0}, 2.0, 1.0)});
}

TEST(Box2dBackend, AutoSubstepsLeaveRoomForACollisionToTripleASpeed) {
  const Scene scene = heavyStrikesLight();
  auto backend = loaded(scene, {{"substeps", 1.0}});
  const double initialEnergy = kineticEnergy(*backend, scene);
  run(*backend, 1.0 / 60.0, 30);

  ASSERT_EQ(backend->counters().ballCollisions, 1u);
  EXPECT_EQ(diagnostic(*backend, "translation_cap_hits"), 0.0);
  // 1e-5 relative: Box2D's float masses (density·πr²) and ~1e-7 rounding per velocity operation.
  EXPECT_NEAR(kineticEnergy(*backend, scene) / initialEnergy, 1.0, 1e-5);
  EXPECT_NEAR(velocityOf(*backend, 1).x, 29900.0 / 101.0, 29900.0 / 101.0 * 1e-5);
  EXPECT_NEAR(velocityOf(*backend, 0).x, 9700.0 / 101.0, 9700.0 / 101.0 * 1e-5);
}

TEST(Box2dBackend, WithoutAutoSubstepsTheStruckBallHitsTheCap) {
  // The same hit in Box2D steps of 1/60 s: 296 m/s would be 4.9 m per step.
  const Scene scene = heavyStrikesLight();
  auto backend = loaded(scene, {{"substeps", 1.0}, {"auto_substeps", 0.0}});
  const double initialEnergy = kineticEnergy(*backend, scene);
  run(*backend, 1.0 / 60.0, 30);

  ASSERT_EQ(backend->counters().ballCollisions, 1u);
  EXPECT_GE(diagnostic(*backend, "translation_cap_hits"), 1.0);
  EXPECT_NEAR(velocityOf(*backend, 1).x, 120.0, 1e-3);
  EXPECT_LT(kineticEnergy(*backend, scene) / initialEnergy, 0.99);
}

TEST(Box2dBackend, DragDecaysSpeedExponentiallyAndBooksTheEnergyItTakes) {
  // c·h = 2/60 per Box2D step with one substep: Box2D's own factor 1/(1 + c·h) would decay too
  // slowly by (c·h)²/2 per step, 3 % after 1 s, so the 1e-4 tolerance separates the two. It
  // covers float rounding of the damping factor and the velocity (~2e-7 per step, 240 steps).
  for (const double substeps : {1.0, 4.0}) {
    SCOPED_TRACE(substeps);
    Scene scene = openSpace({ball({500.0, 500.0}, {3.0, 4.0})});
    scene.world.airResistance = 2.0;  // 1/s
    auto backend = loaded(scene, {{"substeps", substeps}});
    const double initialEnergy = kineticEnergy(*backend, scene);
    run(*backend, 1.0 / 60.0, 60);

    const double expectedSpeed = 5.0 * std::exp(-2.0);
    EXPECT_NEAR(length(velocityOf(*backend, 0)) / expectedSpeed, 1.0, 1e-4);
    // The booked loss is what the damping took: 1e-5 relative, float rounding of the velocity.
    EXPECT_NEAR(backend->counters().dragLoss, initialEnergy - kineticEnergy(*backend, scene),
                1e-5 * initialEnergy);
  }
}

TEST(Box2dBackend, DragLossUnderGravityIsWhatDampingTakesAfterGravityActs) {
  // Box2D adds h·g to the velocity and then damps it, so each step's loss is
  // ½ m (|v + h g|² − |v'|²). Recomputed here from the velocities before and after every step.
  const double dt = 1.0 / 60.0;
  const Vec2 gravity{0.0, -9.81};
  Scene scene = openSpace({ball({500.0, 900.0}, {1.0, 0.0}, 0.5, 2.0)});
  scene.world.gravity = gravity;
  scene.world.airResistance = 1.0;
  auto backend = loaded(scene, {{"substeps", 1.0}});

  double expectedLoss = 0.0;  // J
  for (int i = 0; i < 60; ++i) {
    const Vec2 before = velocityOf(*backend, 0);
    backend->step(dt, {});
    const Vec2 after = velocityOf(*backend, 0);
    expectedLoss += 0.5 * 2.0 * (lengthSquared(before + dt * gravity) - lengthSquared(after));
  }
  ASSERT_GT(expectedLoss, 10.0);
  // 1e-3 J of ~30 J: float h and g against double here, ~1e-7 relative on |v|² ≈ 100 m²/s²
  // per step over 60 steps. Leaving out the gravity term would be off by ~2 J.
  EXPECT_NEAR(backend->counters().dragLoss, expectedLoss, 1e-3);
}

TEST(Box2dBackend, WallsThatAreOffLetBallsLeaveTheBox) {
  Scene scene = boxScene(16.0, 9.0, {ball({8.0, 4.5}, {10.0, 0.0})});
  scene.world.walls = {false, false, false, false};
  auto backend = loaded(scene);
  run(*backend, 1.0 / 240.0, 240);

  EXPECT_NEAR(positionOf(*backend, 0).x, 18.0, 1e-3);
  EXPECT_EQ(backend->counters().wallCollisions, 0u);
}

TEST(Box2dBackend, SetWorldTurnsWallsOffAndOnLive) {
  const Scene scene = boxScene(16.0, 9.0, {ball({14.0, 4.5}, {3.0, 0.0})});
  WorldSettings rightWallOff = scene.world;
  rightWallOff.walls.right = false;

  auto leaving = loaded(scene);
  leaving->setWorld(rightWallOff);
  run(*leaving, 1.0 / 240.0, 240);
  EXPECT_NEAR(positionOf(*leaving, 0).x, 17.0, 1e-3);

  Scene startsOff = scene;
  startsOff.world = rightWallOff;
  auto bouncing = loaded(startsOff);
  bouncing->setWorld(scene.world);
  run(*bouncing, 1.0 / 240.0, 240);
  EXPECT_NEAR(velocityOf(*bouncing, 0).x, -3.0, 1e-5);
  EXPECT_EQ(bouncing->counters().wallCollisions, 1u);
}

TEST(Box2dBackend, BallCollisionsOffLetBallsPassThroughEachOtherButNotWalls) {
  const Scene scene =
      boxScene(16.0, 9.0, {ball({6.0, 4.5}, {2.0, 0.0}), ball({10.0, 4.5}, {-2.0, 0.0})});
  Scene offFromLoad = scene;
  offFromLoad.world.ballCollisions = false;
  auto loadedOff = loaded(offFromLoad);
  auto switchedOff = loaded(scene);
  switchedOff->setWorld(offFromLoad.world);  // refilters live

  for (Backend* backend : {loadedOff.get(), switchedOff.get()}) {
    run(*backend, 1.0 / 240.0, 480);  // fully through each other by t = 2 s
    EXPECT_EQ(velocityOf(*backend, 0).x, 2.0);
    EXPECT_EQ(velocityOf(*backend, 1).x, -2.0);
    EXPECT_NEAR(positionOf(*backend, 0).x, 10.0, 1e-3);
    EXPECT_EQ(backend->counters().ballCollisions, 0u);

    run(*backend, 1.0 / 240.0, 720);  // each reaches the opposite wall at t = 4.75 s
    EXPECT_NEAR(velocityOf(*backend, 0).x, -2.0, 1e-5);
    EXPECT_NEAR(velocityOf(*backend, 1).x, 2.0, 1e-5);
    EXPECT_EQ(backend->counters().wallCollisions, 2u);
  }
}

TEST(Box2dBackend, ForcesActAsAnImpulseAtTheStartOfTheStep) {
  // 4 N on 2 kg for 0.01 s: Δv = 0.02 m/s at the start, so the ball already moves 0.02 m/s ×
  // 0.01 s = 2e-4 m in that step. Float: ulp(1 m) = 1.2e-7, ulp(0.02 m/s) = 1.9e-9.
  auto backend = loaded(
      boxScene(16.0, 9.0, {ball({1.0, 4.5}, {0.0, 0.0}, 0.5, 2.0), ball({8.0, 4.5}, {0.0, 0.0})}));
  const std::vector<Vec2> forces = {{4.0, 0.0}, {0.0, 0.0}};
  backend->step(0.01, forces);

  EXPECT_NEAR(velocityOf(*backend, 0).x, 0.02, 1e-8);
  EXPECT_NEAR(positionOf(*backend, 0).x, 1.0 + 2e-4, 1e-6);
  EXPECT_EQ(velocityOf(*backend, 1).x, 0.0);
}

TEST(Box2dBackend, OneWallBounceCountsOnceAndDeliversTwiceTheMomentum) {
  const double mass = 2.0;   // kg
  const double speed = 3.0;  // m/s
  const Scene scene = boxScene(16.0, 9.0, {ball({12.0, 4.5}, {speed, 0.0}, 0.5, mass)});
  auto backend = loaded(scene);
  run(*backend, 1.0 / 240.0, 480);  // bounces at t = 7/6 s, stays in contact a step or two

  const BackendCounters counters = backend->counters();
  EXPECT_EQ(counters.wallCollisions, 1u);
  EXPECT_EQ(counters.ballCollisions, 0u);
  EXPECT_NEAR(counters.wallImpulse, 2.0 * mass * speed, 2.0 * mass * speed * 1e-5);

  backend->load(scene);  // load starts the counts again
  EXPECT_EQ(backend->counters().wallCollisions, 0u);
  EXPECT_EQ(backend->counters().wallImpulse, 0.0);
  EXPECT_EQ(diagnostic(*backend, "box2d_steps"), 0.0);
}

TEST(Box2dBackend, BallSlidingAlongAWallKeepsItsVelocityAndCountsOneCollision) {
  // The floor of a 40 m box is several square pieces (wall_bodies.cpp, 7 m each here); the ball
  // slides over 4 seams between them, pressed 1 mm into the floor (less than Box2D's 5 mm slop,
  // so position correction leaves it there and it stays touching). A piece's corner at a seam
  // would push a ball that overlaps it (a "ghost" collision): up to 6% of its speed, reflected
  // off a normal tilted by up to √(2·1 mm/0.51 m), would appear as vertical velocity.
  const double speed = 3.0;  // m/s
  auto backend = loaded(boxScene(40.0, 9.0, {ball({2.0, 0.499}, {speed, 0.0})}));
  run(*backend, 1.0 / 60.0, 600);  // at x = 32 after 10 s, far from the right wall

  // 1e-6 m/s: float rounding of 3 m/s through the solver, as elsewhere; any ghost is ≥ 1e-3.
  EXPECT_NEAR(velocityOf(*backend, 0).x, speed, 1e-6);
  EXPECT_NEAR(velocityOf(*backend, 0).y, 0.0, 1e-6);
  EXPECT_NEAR(positionOf(*backend, 0).y, 0.499, 1e-6);
  EXPECT_EQ(backend->counters().wallCollisions, 1u);
}

TEST(Box2dBackend, DroppedBallCountsEachBounceOnceAndWallImpulseBalancesMomentum) {
  // Dropped from 1.5 m above the floor contact: bounces at t ≈ 0.55, 1.66 and 2.77 s. Each
  // contact spans a step or two (5.4 m/s against h = 1/960 s) and must count once.
  const double mass = 1.5;                                               // kg
  const double gravity = static_cast<double>(static_cast<float>(9.81));  // Box2D's float g
  Scene scene = boxScene(16.0, 9.0, {ball({8.0, 2.0}, {0.0, 0.0}, 0.5, mass)});
  scene.world.gravity = {0.0, -9.81};
  auto backend = loaded(scene);
  run(*backend, 1.0 / 240.0, 720);

  EXPECT_EQ(backend->counters().wallCollisions, 3u);
  // Momentum balance: the floor's impulse is m·Δv_y + m·g·t. 5e-3 N·s of ~44: float rounding of
  // v ≈ 5 m/s (ulp 5e-7) over 2880 gravity increments. A missed bounce would be 16 N·s.
  const double expected = mass * velocityOf(*backend, 0).y + mass * gravity * 3.0;
  EXPECT_NEAR(backend->counters().wallImpulse, expected, 5e-3);
}

TEST(Box2dBackend, SetBallChangesRadiusAndMass) {
  // Centres 1.1 m apart across the path: balls of radius 0.5 miss; radius 0.7 makes them hit.
  auto grown =
      loaded(boxScene(16.0, 9.0, {ball({4.0, 4.5}, {2.0, 0.0}), ball({8.0, 5.6}, {0.0, 0.0})}));
  grown->setBall(0, ball({4.0, 4.5}, {2.0, 0.0}, 0.7, 1.0));
  run(*grown, 1.0 / 240.0, 480);
  EXPECT_EQ(grown->counters().ballCollisions, 1u);  // so the radius is 0.7

  // A 3 kg striker on a 1 kg ball at rest: v' = (3−1)/4 · 2 = 1 and 2·3/4 · 2 = 3 m/s.
  auto heavier =
      loaded(boxScene(16.0, 9.0, {ball({6.0, 4.5}, {2.0, 0.0}), ball({10.0, 4.5}, {0.0, 0.0})}));
  heavier->setBall(0, ball({6.0, 4.5}, {2.0, 0.0}, 0.5, 3.0));
  run(*heavier, 1.0 / 240.0, 480);
  EXPECT_NEAR(velocityOf(*heavier, 0).x, 1.0, 1e-5);
  EXPECT_NEAR(velocityOf(*heavier, 1).x, 3.0, 1e-5);
}

TEST(Box2dBackend, ReportsTheNearestFloatsOfTheLoadedState) {
  // Positions and velocities are Box2D's float state: the nearest floats, widened exactly.
  const Scene scene =
      boxScene(16.0, 9.0, {{{1.1, 2.2}, {0.3, -0.7}, 0.333333333333, 0.123456789, 0x123456}});
  auto backend = loaded(scene);
  const testing::State state = testing::readState(*backend);
  ASSERT_EQ(state.positions.size(), 1u);
  EXPECT_EQ(state.positions[0].x, static_cast<double>(static_cast<float>(1.1)));
  EXPECT_EQ(state.positions[0].y, static_cast<double>(static_cast<float>(2.2)));
  EXPECT_EQ(state.velocities[0].x, static_cast<double>(static_cast<float>(0.3)));
  EXPECT_EQ(state.velocities[0].y, static_cast<double>(static_cast<float>(-0.7)));
}

TEST(Box2dBackend, BulletsStopSmallFastBallsTunnellingThroughEachOther) {
  // Radius 5 cm, closing at 200 m/s: 0.83 m per Box2D step, and the start is chosen so no step
  // begins with them overlapping, so discrete collision misses the hit entirely.
  const Scene scene = openSpace({ball({100.0, 500.0}, {100.0, 0.0}, 0.05, 1.0),
                                 ball({110.4, 500.0}, {-100.0, 0.0}, 0.05, 1.0)});
  auto tunnelling = loaded(scene);
  run(*tunnelling, 1.0 / 60.0, 10);
  EXPECT_EQ(tunnelling->counters().ballCollisions, 0u);
  EXPECT_EQ(velocityOf(*tunnelling, 0).x, 100.0);

  auto bulletsFromLoad = loaded(scene, {{"bullets", 1.0}});
  auto bulletsSetLive = loaded(scene);
  bulletsSetLive->setOption("bullets", 1.0);
  for (Backend* bullets : {bulletsFromLoad.get(), bulletsSetLive.get()}) {
    run(*bullets, 1.0 / 60.0, 10);
    EXPECT_EQ(bullets->counters().ballCollisions, 1u);
    EXPECT_NEAR(velocityOf(*bullets, 0).x, -100.0, 1e-3);
    EXPECT_NEAR(velocityOf(*bullets, 1).x, 100.0, 1e-3);
  }
}

/// m: how far beyond a wall's face Box2D's own continuous collision may leave a ball's centre
/// (3.25 linear slops: wall_containment.h).
constexpr double kWallSlack = 3.25 * 0.005;

/// The deepest any centre lies beyond the box's faces, m (0 when every centre is inside).
double deepestBeyondTheWalls(const Backend& backend, const Box& box) {
  double deepest = 0.0;
  for (const Vec2 p : testing::readState(backend).positions)
    deepest = std::max({deepest, -p.x, p.x - box.width, -p.y, p.y - box.height});
  return deepest;
}

TEST(Box2dBackend, BallsThatContinuousCollisionLetsIntoAWallArePutBack) {
  // Random invariant case 1169 reduced to the three balls it needs. Under g = 680 m/s² a 0.65 mm,
  // 0.3 mg bullet lies against the left wall, within the continuous collision's target depth:
  // every time-of-impact search finds it touching at once, and eight such sub-steps use up the
  // contact's b2_maxSubSteps for the Box2D step. Ball 1 then strikes it towards the wall and
  // nothing stops it: it ends the first step 0.47 m inside the wall.
  Scene scene = boxScene(
      2.319472266828711, 1.6037904373359495,
      {ball({0.0899213297200003, 1.1537422371380754}, {0.0012945380415835576, -0.05648520321819594},
            0.06091602097005677, 0.13047094610938492),
       ball({0.2750853085531262, 0.9538636377398053},
            {0.034040681807824415, -0.0073671312863590015}, 0.04197124557847674,
            0.02837816939633601),
       ball({0.24574617796067502, 0.7808310072450552},
            {-0.0028037288058744224, -0.028612964678815692}, 0.0006464735420135754,
            2.9776851167587363e-07)});
  scene.world.gravity = {-245.6196752217671, 631.7112901599689};
  auto backend = loaded(scene, {{"substeps", 2.0},
                                {"velocity_iterations", 3.0},
                                {"position_iterations", 1.0},
                                {"bullets", 1.0},
                                {"auto_substeps", 0.0}});
  for (int step = 0; step < 100; ++step) {
    backend->step(0.038474063078296733, {});
    ASSERT_LE(deepestBeyondTheWalls(*backend, scene.box), kWallSlack) << "step " << step;
  }
  EXPECT_GE(diagnostic(*backend, "balls_put_back"), 1.0);
}

TEST(Box2dBackend, ABallBeyondAWallComesBackWithItsVelocityReflected) {
  // Where Box2D's continuous collision gives up (above), a ball can end a Box2D step deeper in a
  // wall than half its 8 m thickness, and Box2D then pushes it out through the far side: 20 m
  // out, beyond the wall, nothing would ever bring it back. The adapter puts it back on the
  // wall's face and turns it back as an elastic wall would.
  const double mass = 2.0;
  const Box box{16.0, 9.0};
  auto backend = loaded(boxScene(box.width, box.height, {ball({8.0, 2.0}, {0.0, 0.0}, 0.5, mass)}));
  backend->setBall(0, ball({-20.0, 2.0}, {-3.0, 1.0}, 0.5, mass));
  backend->step(1.0 / 240.0, {});

  EXPECT_LE(deepestBeyondTheWalls(*backend, box), kWallSlack);
  EXPECT_EQ(velocityOf(*backend, 0).x, 3.0);
  EXPECT_EQ(velocityOf(*backend, 0).y, 1.0);
  EXPECT_NEAR(backend->counters().wallImpulse, 2.0 * mass * 3.0, 1e-9);
  EXPECT_EQ(diagnostic(*backend, "balls_put_back"), 1.0);
  run(*backend, 1.0 / 240.0, 240);
  EXPECT_GT(positionOf(*backend, 0).x, 2.0);  // on its way across the box
  EXPECT_LE(deepestBeyondTheWalls(*backend, box), kWallSlack);
}

TEST(Box2dBackend, OptionsHaveTheirDefaultsAndRejectBadValues) {
  auto backend = makeBox2dBackend();
  EXPECT_EQ(backend->options().value("substeps"), 4.0);
  EXPECT_EQ(backend->options().value("velocity_iterations"), 8.0);
  EXPECT_EQ(backend->options().value("position_iterations"), 3.0);
  EXPECT_EQ(backend->options().value("bullets"), 0.0);
  EXPECT_EQ(backend->options().value("auto_substeps"), 1.0);

  EXPECT_THROW(backend->setOption("warm_starting", 1.0), std::invalid_argument);
  EXPECT_THROW(backend->setOption("substeps", 0.0), std::invalid_argument);
  EXPECT_THROW(backend->setOption("substeps", 1001.0), std::invalid_argument);
  EXPECT_THROW(backend->setOption("substeps", 2.5), std::invalid_argument);
  EXPECT_THROW(backend->setOption("velocity_iterations", 0.0), std::invalid_argument);
  EXPECT_THROW(backend->setOption("bullets", 2.0), std::invalid_argument);
  EXPECT_THROW(backend->setOption("auto_substeps", 0.5), std::invalid_argument);
  EXPECT_NO_THROW(backend->setOption("position_iterations", 0.0));
  EXPECT_NO_THROW(backend->setOptionFromText("substeps=1000"));
  EXPECT_EQ(backend->options().value("substeps"), 1000.0);
}

}  // namespace
}  // namespace fooball
