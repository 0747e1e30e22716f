// The Chipmunk adapter's own traps (backends/chipmunk/), beyond the contract every backend meets
// (tests/conformance_test.cpp): what it does where Chipmunk alone would lose a ball or hang.

#include "chipmunk/chipmunk_backend.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "backend_state.h"

namespace fooball {
namespace {

BallDef ball(Vec2 position, Vec2 velocity, double radius = 0.5, double mass = 1.0) {
  return {position, velocity, radius, mass, 0xe0a030};
}

Scene boxScene(double width, double height, std::vector<BallDef> balls) {
  Scene scene;
  scene.name = "chipmunk test";
  scene.box = {width, height};
  scene.balls = std::move(balls);
  return scene;
}

double diagnostic(const Backend& backend, std::string_view name) {
  for (const Diagnostic& d : backend.diagnostics()) {
    if (d.name == name) return d.value;
  }
  ADD_FAILURE() << "no diagnostic named " << name;
  return 0.0;
}

TEST(ChipmunkBackend, ABallThatCrossesAWallInOneSubstepIsMirroredBackWithItsSpeed) {
  // 600 m/s at 4 substeps of 1/240 s: 2.5 m a substep, from 0.05 m before the right wall's
  // contact: the centre ends 2.4 m beyond the face, far past the wall's axis (thickness: the
  // radius), where Chipmunk alone would push it out on the far side. Mirrored to 13.6 m, it flies
  // on for three substeps to 6.1 m.
  const double mass = 2.0;
  const std::unique_ptr<Backend> backend = makeChipmunkBackend();
  backend->load(boxScene(16.0, 9.0, {ball({15.9, 4.5}, {600.0, 0.0}, 0.05, mass)}));
  backend->step(1.0 / 60.0, {});
  const testing::State state = testing::readState(*backend);
  EXPECT_NEAR(state.positions[0].x, 6.1, 1e-9);
  EXPECT_EQ(state.velocities[0].x, -600.0);  // no gravity: the speed kept exactly
  EXPECT_EQ(diagnostic(*backend, "balls_brought_back"), 1.0);
  EXPECT_EQ(backend->counters().wallCollisions, 1u);  // Chipmunk never saw a contact
  EXPECT_NEAR(backend->counters().wallImpulse, 2.0 * mass * 600.0, 1e-9);
}

TEST(ChipmunkBackend, TheLiftOfAMirroredBallIsPaidFromItsSpeed) {
  // Under g = 10 m/s², one substep of 10 ms carries the ball at 50 m/s from 0.1 m to 0.401 m
  // below the floor. Mirrored 0.802 m up, it leaves with ½v'² = ½v² − g·0.802: the energy it had
  // at the end of the substep, no more.
  Scene scene = boxScene(4.0, 4.0, {ball({2.0, 0.1}, {0.0, -50.0}, 0.01, 1.0)});
  scene.world.gravity = {0.0, -10.0};
  const std::unique_ptr<Backend> backend = makeChipmunkBackend();
  backend->setOption("substeps", 1.0);
  backend->load(scene);
  const auto energy = [&] {  // J per kg
    const testing::State state = testing::readState(*backend);
    return 0.5 * lengthSquared(state.velocities[0]) + 10.0 * state.positions[0].y;
  };
  const double kicked = 50.0 + 10.0 * 0.01;  // m/s, the speed Chipmunk moved it with
  const double atSubstepEnd = 0.5 * kicked * kicked + 10.0 * (0.1 - kicked * 0.01);
  backend->step(0.01, {});
  const testing::State state = testing::readState(*backend);
  EXPECT_NEAR(state.positions[0].y, kicked * 0.01 - 0.1, 1e-12);
  EXPECT_GT(state.velocities[0].y, 0.0);
  EXPECT_NEAR(energy(), atSubstepEnd, 1e-9 * atSubstepEnd);
}

TEST(ChipmunkBackend, ABallTooFarForTheSpatialHashMovesTheSpaceToTheTree) {
  // Balls of 1 mm in a 1 m box: hash cells of 2 mm, whose int cell numbers overflow 2^31 at
  // 4'300 km. A ball leaving through the open left wall at 1e6 m/s passes 2^30 cells (2'100 km)
  // after 2.1 s, where the adapter leaves the hash; without that, Chipmunk's hash would loop for
  // ever once the ball passes 4'300 km, after 4.3 s (broadphase.h).
  Scene scene =
      boxScene(1.0, 1.0, {ball({0.5, 0.5}, {-1e6, 0.0}, 1e-3), ball({0.2, 0.2}, {0.0, 0.0}, 1e-3)});
  scene.world.walls.left = false;
  const std::unique_ptr<Backend> backend = makeChipmunkBackend();
  backend->setOption("spatial_hash", 1.0);
  backend->load(scene);
  for (int step = 0; step < 300; ++step)  // 5 s
    backend->step(1.0 / 60.0, {});
  const testing::State state = testing::readState(*backend);
  EXPECT_NEAR(state.positions[0].x, 0.5 - 5e6, 1e-6 * 5e6);
  EXPECT_EQ(state.positions[1], (Vec2{0.2, 0.2}));
  EXPECT_EQ(diagnostic(*backend, "spatial_hash_left"), 1.0);
}

}  // namespace
}  // namespace fooball
