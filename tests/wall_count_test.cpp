// What every backend counts as a wall collision (backends/common/wall_touches.h): one reversal of
// a ball's approach to a wall. A pile resting on the floor begins none; a gas's counted bounces
// are the ones its walls' impulse adds up to; one ball bouncing counts one per bounce. The suite
// is instantiated over registeredBackends(); a backend's bounds are its row in
// tests/backend_profiles.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "backend_profiles.h"
#include "backend_state.h"
#include "fooball/backend.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;

class WallCount : public ::testing::TestWithParam<BackendInfo> {
 protected:
  std::unique_ptr<Backend> make() const {
    return testing::createWithOptions(GetParam().name, bounds().options);
  }
  const testing::WallCountBounds& bounds() const {
    return testing::profileFor(GetParam().name).wallCount;
  }
};

using testing::kDt;
using testing::runFor;

/// A pile at rest under 9.81 m/s² in a 16 × 9 m box: balls of radius 0.1 m, touching, in four
/// rows stacked as tightly as disks go (each ball in the groove of two below): 80, 79, 78 and 77
/// balls, 314 in all, the bottom row spanning the floor from wall to wall.
Scene restingPile() {
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -9.81};
  const double r = 0.1;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 80 - row; ++column) {
      scene.balls.push_back(
          ball({r * (1 + row + 2 * column), r * (1.0 + std::sqrt(3.0) * row)}, {0.0, 0.0}, r));
    }
  }
  return scene;
}

TEST_P(WallCount, APileAtRestBeginsNoWallCollisions) {
  auto backend = make();
  backend->load(restingPile());
  runFor(*backend, 1.0);  // its contacts begin, and whatever settling the method does is done
  const std::uint64_t settled = backend->counters().wallCollisions;
  const double seconds = 2.0;
  runFor(*backend, seconds);
  const double perSecond =
      static_cast<double>(backend->counters().wallCollisions - settled) / seconds;
  // A count per substep of every ball on the floor would be 80 × 60 × the substeps a second.
  EXPECT_LE(perSecond, bounds().restingPilePerSecond)
      << "new wall collisions per second in a pile at rest";
}

/// 300 balls of radius 0.1 m, mass 1 kg, each moving at (±1, ±1) m/s, in a 16 × 9 m box without
/// gravity and with ball collisions off: every bounce turns a velocity component of 1 m/s, so
/// gives the wall 2 N·s.
Scene gasOfEqualNormalSpeeds() {
  Scene scene = testing::gas(300, 5);
  scene.world.ballCollisions = false;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    BallDef& b = scene.balls[i];
    b.radius = 0.1;
    b.mass = 1.0;
    b.velocity = {i % 2 == 0 ? 1.0 : -1.0, i % 4 < 2 ? 1.0 : -1.0};
  }
  return scene;
}

/// The bounces a ball starting at `start` (m) moving at `speed` (m/s) makes in `seconds` between
/// walls at `radius` and `length − radius` (m): its unfolded path crosses one every `length − 2
/// radius`.
std::uint64_t bouncesAlong(double start, double speed, double radius, double length,
                           double seconds) {
  const double span = length - 2.0 * radius;
  const double toFirst = speed > 0.0 ? length - radius - start : start - radius;  // m
  const double travel = std::abs(speed) * seconds;
  return travel < toFirst ? 0 : 1 + static_cast<std::uint64_t>((travel - toFirst) / span);
}

TEST_P(WallCount, AGasCountsTheBouncesItsWallImpulseAddsUpTo) {
  const Scene scene = gasOfEqualNormalSpeeds();
  const double seconds = 30.0;
  std::uint64_t expected = 0;
  for (const BallDef& b : scene.balls) {
    expected += bouncesAlong(b.position.x, b.velocity.x, b.radius, scene.box.width, seconds);
    expected += bouncesAlong(b.position.y, b.velocity.y, b.radius, scene.box.height, seconds);
  }
  auto backend = make();
  backend->load(scene);
  runFor(*backend, seconds);
  const BackendCounters counters = backend->counters();
  const auto counted = static_cast<double>(counters.wallCollisions);
  // Each bounce gives 2 m v_n = 2 N·s.
  const double fromImpulse = counters.wallImpulse / 2.0;
  ASSERT_GT(expected, 1000u) << "the test needs bounces to mean much";
  const double tolerance = bounds().gasRelative * static_cast<double>(expected);
  EXPECT_NEAR(counted, static_cast<double>(expected), tolerance) << "counted against the paths";
  EXPECT_NEAR(counted, fromImpulse, tolerance) << "counted against the wall impulse / (2 m v_n)";
}

TEST_P(WallCount, OneBallBouncingCountsOnePerBounce) {
  // Dropped from rest 4 m above the floor: it lands after t₁ = √(2·4/9.81) = 0.903 s and every
  // 2 t₁ = 1.806 s after that, so 5 times in 9 s (the 6th at 9.93 s).
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -9.81};
  scene.balls.push_back(ball({8.0, 4.5}, {0.0, 0.0}, 0.5));
  auto backend = make();
  backend->load(scene);
  runFor(*backend, 9.0);
  EXPECT_EQ(backend->counters().wallCollisions, 5u);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, WallCount, ::testing::ValuesIn(registeredBackends()),
                         [](const auto& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace fooball
