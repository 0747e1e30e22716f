// addRandomBalls: reproducible, inside the box, apart from each other and from the balls already
// there, within the requested ranges, linear in the ball count, and clear when they cannot fit.

#include "fooball/random_balls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fooball/scene_file.h"

namespace fooball {
namespace {

/// Floating-point slack for "inside" and "apart": the placement is exact up to rounding.
constexpr double kRounding = 1e-12;  // m

Scene emptyBox(double width = 16.0, double height = 9.0) {
  Scene scene;
  scene.box = {width, height};
  return scene;
}

RandomBalls spec(std::size_t count, std::uint64_t seed = 7) {
  RandomBalls random;
  random.count = count;
  random.minRadius = 0.03;
  random.maxRadius = 0.1;
  random.minSpeed = 0.5;
  random.maxSpeed = 3.0;
  random.density = 2.0;
  random.seed = seed;
  return random;
}

Scene randomScene(std::size_t count, std::uint64_t seed = 7) {
  Scene scene = emptyBox();
  addRandomBalls(scene, spec(count, seed));
  return scene;
}

std::string addError(Scene scene, const RandomBalls& random) {
  try {
    addRandomBalls(scene, random);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

/// Pairs of balls closer than their radii allow, found by sweeping along x: balls sorted by
/// the left edge of their reach, each compared only with those whose reach starts before its own
/// ends. O(N log N) for the spread-out balls here.
std::size_t overlappingPairs(const std::vector<BallDef>& balls) {
  std::vector<std::size_t> order(balls.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const auto left = [&](std::size_t i) { return balls[i].position.x - balls[i].radius; };
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return left(a) < left(b); });
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const BallDef& a = balls[order[i]];
    for (std::size_t j = i + 1; j < order.size() && left(order[j]) < a.position.x + a.radius; ++j) {
      const BallDef& b = balls[order[j]];
      if (length(a.position - b.position) < a.radius + b.radius - kRounding) ++pairs;
    }
  }
  return pairs;
}

std::uint64_t bitsHash(const std::vector<BallDef>& balls) {
  // FNV-1a over every field's bits.
  std::uint64_t hash = 0xcbf29ce484222325u;
  auto mix = [&hash](std::uint64_t bits) {
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xffu;
      hash *= 0x100000001b3u;
    }
  };
  for (const BallDef& ball : balls) {
    for (const double value : {ball.position.x, ball.position.y, ball.velocity.x, ball.velocity.y,
                               ball.radius, ball.mass})
      mix(std::bit_cast<std::uint64_t>(value));
    mix(ball.color);
  }
  return hash;
}

TEST(RandomBalls, SameSeedGivesTheSameBallsBitForBit) {
  EXPECT_EQ(bitsHash(randomScene(2000, 11).balls), bitsHash(randomScene(2000, 11).balls));
}

TEST(RandomBalls, SeedGivesTheSameBallsOnEveryPlatform) {
  // Pinned: SplitMix64 and integer-to-double steps only, no library distributions or sin/cos.
  // If this changes, scene files with random_balls now load differently: a format change.
  EXPECT_EQ(bitsHash(randomScene(500, 7).balls), 15219314348766092071u);
}

TEST(RandomBalls, DifferentSeedsGiveDifferentBalls) {
  const Scene a = randomScene(500, 1);
  const Scene b = randomScene(500, 2);
  std::size_t samePositions = 0;
  for (std::size_t i = 0; i < a.balls.size(); ++i)
    samePositions += a.balls[i].position == b.balls[i].position ? 1 : 0;
  EXPECT_EQ(samePositions, 0u);
}

TEST(RandomBalls, EveryBallLiesInsideTheBox) {
  const Scene scene = randomScene(3000);
  for (const BallDef& ball : scene.balls) {
    EXPECT_GE(ball.position.x - ball.radius, -kRounding);
    EXPECT_LE(ball.position.x + ball.radius, 16.0 + kRounding);
    EXPECT_GE(ball.position.y - ball.radius, -kRounding);
    EXPECT_LE(ball.position.y + ball.radius, 9.0 + kRounding);
  }
}

TEST(RandomBalls, NoTwoBallsOverlap) {
  const Scene scene = randomScene(3000);
  EXPECT_EQ(overlappingPairs(scene.balls), 0u);
  EXPECT_NO_THROW(validateScene(scene, "random"));
}

TEST(RandomBalls, RadiiSpeedsMassesAndColorsFollowTheSpec) {
  const Scene scene = randomScene(3000);
  ASSERT_EQ(scene.balls.size(), 3000u);
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallDef& ball = scene.balls[i];
    EXPECT_GE(ball.radius, 0.03);
    EXPECT_LE(ball.radius, 0.1);
    EXPECT_GE(length(ball.velocity), 0.5 - kRounding);
    EXPECT_LE(length(ball.velocity), 3.0 + kRounding);
    EXPECT_EQ(ball.mass, diskMass(ball.radius, 2.0));
    EXPECT_EQ(ball.color, defaultBallColor(i));
  }
}

TEST(RandomBalls, PositionsAndDirectionsSpreadEvenly) {
  const Scene scene = randomScene(3000);
  std::size_t left = 0;
  std::size_t lower = 0;
  std::size_t movingRight = 0;
  std::size_t movingUp = 0;
  for (const BallDef& ball : scene.balls) {
    left += ball.position.x < 8.0 ? 1 : 0;
    lower += ball.position.y < 4.5 ? 1 : 0;
    movingRight += ball.velocity.x > 0.0 ? 1 : 0;
    movingUp += ball.velocity.y > 0.0 ? 1 : 0;
  }
  // Binomial(3000, 1/2) has a standard deviation of 27; 150 is more than 5 of them.
  for (const std::size_t half : {left, lower, movingRight, movingUp}) {
    EXPECT_NEAR(static_cast<double>(half), 1500.0, 150.0);
  }
}

TEST(RandomBalls, EqualMinAndMaxGiveExactlyThatValue) {
  Scene scene = emptyBox();
  addRandomBalls(scene, {100, 0.2, 0.2, 1.5, 1.5, 1.0, 3});
  for (const BallDef& ball : scene.balls) {
    EXPECT_EQ(ball.radius, 0.2);
    EXPECT_NEAR(length(ball.velocity), 1.5, kRounding);
  }
}

TEST(RandomBalls, KeepsAndAvoidsTheBallsAlreadyThere) {
  Scene scene = emptyBox();
  scene.balls = {{{8.0, 4.5}, {1.0, 0.0}, 2.0, 5.0, 0x123456},
                 {{1.0, 1.0}, {}, 0.7, 1.0, 0x654321},
                 {{15.5, 8.5}, {}, 0.3, 1.0, 0x111111}};
  const std::vector<BallDef> before = scene.balls;
  addRandomBalls(scene, spec(2000));
  ASSERT_EQ(scene.balls.size(), 2003u);
  EXPECT_EQ(bitsHash({scene.balls.begin(), scene.balls.begin() + 3}), bitsHash(before));
  for (std::size_t i = 3; i < scene.balls.size(); ++i) {
    for (const BallDef& existing : before) {
      EXPECT_GE(length(scene.balls[i].position - existing.position),
                scene.balls[i].radius + existing.radius - kRounding);
    }
    EXPECT_EQ(scene.balls[i].color, defaultBallColor(i));
  }
  EXPECT_EQ(overlappingPairs(scene.balls), 0u);
}

TEST(RandomBalls, IgnoresBallsOutsideTheBoxWhenPlacing) {
  Scene scene = emptyBox(4.0, 2.0);
  scene.world.walls = {false, false, false, false};
  scene.balls = {{{-50.0, 1.0}, {}, 1.0, 1.0, 0}, {{2.0, 1e12}, {}, 1.0, 1.0, 0}};
  addRandomBalls(scene, {8, 0.5, 0.5, 1.0, 1.0, 1.0, 1});
  EXPECT_EQ(scene.balls.size(), 10u);
}

TEST(RandomBalls, ZeroCountAddsNothing) {
  Scene scene = emptyBox();
  addRandomBalls(scene, spec(0));
  EXPECT_TRUE(scene.balls.empty());
}

TEST(RandomBalls, FillsTheBoxToItsStatedCapacity) {
  // A 4 × 2 m box holds a lattice of 4 × 2 cells 1 m wide: 8 balls of radius 0.5, no more.
  Scene scene = emptyBox(4.0, 2.0);
  addRandomBalls(scene, {8, 0.5, 0.5, 1.0, 1.0, 1.0, 5});
  EXPECT_EQ(scene.balls.size(), 8u);
  EXPECT_EQ(overlappingPairs(scene.balls), 0u);
  EXPECT_EQ(addError(emptyBox(4.0, 2.0), {9, 0.5, 0.5, 1.0, 1.0, 1.0, 5}),
            "random_balls.count: 9 balls of radius up to 0.5 m do not fit: the box has room for "
            "at most 8");
}

TEST(RandomBalls, CannotFitErrorCountsTheRoomLeftByExistingBalls) {
  Scene scene = emptyBox(4.0, 2.0);
  scene.balls = {{{1.0, 1.0}, {}, 0.9, 1.0, 0}};
  EXPECT_EQ(addError(scene, {8, 0.5, 0.5, 1.0, 1.0, 1.0, 5}),
            "random_balls.count: 8 balls of radius up to 0.5 m do not fit: the box has room for "
            "at most 4 beside the balls already in it");
}

TEST(RandomBalls, BoxSmallerThanOneBallHasNoRoom) {
  EXPECT_EQ(addError(emptyBox(0.5, 9.0), {1, 0.1, 0.3, 1.0, 1.0, 1.0, 5}),
            "random_balls.count: 1 balls of radius up to 0.3 m do not fit: the box has room for "
            "at most 0");
}

TEST(RandomBalls, HugeBoxWithFewTinyBallsNeedsNoHugeLattice) {
  // A diameter-wide lattice here would have 2.5e17 cells.
  Scene scene = emptyBox(1e6, 1e6);
  addRandomBalls(scene, {10, 0.001, 0.001, 1.0, 1.0, 1.0, 5});
  EXPECT_EQ(scene.balls.size(), 10u);
  EXPECT_NO_THROW(validateScene(scene, "huge"));
}

TEST(RandomBalls, SpecIsCheckedWithPlacesOfTheSceneFile) {
  EXPECT_EQ(addError(emptyBox(), {1, -0.1, 0.2, 1.0, 1.0, 1.0, 1}),
            "random_balls.radius: must be [min, max] with 0 < min <= max (got [-0.1, 0.2])");
  EXPECT_EQ(addError(emptyBox(), {1, 0.1, std::nan(""), 1.0, 1.0, 1.0, 1}),
            "random_balls.radius: must be [min, max] with 0 < min <= max (got [0.1, nan])");
  EXPECT_EQ(addError(emptyBox(), {1, 0.1, 2e6, 1.0, 1.0, 1.0, 1}),
            "random_balls.radius: max must be at most 1000000 m (got 2e+06)");
  EXPECT_EQ(addError(emptyBox(), {1, 0.1, 0.2, 1.0, INFINITY, 1.0, 1}),
            "random_balls.speed: must be [min, max] with 0 <= min <= max (got [1, inf])");
  EXPECT_EQ(addError(emptyBox(), {1, 0.1, 0.2, 1.0, 1.0, -1.0, 1}),
            "random_balls.density: must be > 0 (got -1)");
  EXPECT_EQ(addError(emptyBox(), {1, 1e-200, 0.2, 1.0, 1.0, 1.0, 1}),
            "random_balls.density: gives balls of radius 1e-200 m a mass of 0 kg");
  EXPECT_EQ(addError(emptyBox(), {kMaxBalls + 1, 0.1, 0.2, 1.0, 1.0, 1.0, 1}),
            "random_balls.count: must be at most 2000000 (got 2000001)");
}

TEST(RandomBalls, PlacesAMillionBallsInLinearTime) {
  // Just run it: the lattice, not rejection, makes this fast (no timing assertion in a unit
  // test; the time is recorded in the test's XML output).
  Scene scene = emptyBox();
  const auto start = std::chrono::steady_clock::now();
  addRandomBalls(scene, {1'000'000, 0.003, 0.005, 0.1, 1.0, 1.0, 9});
  const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
  RecordProperty("placement_ms", std::to_string(elapsed.count()));
  ASSERT_EQ(scene.balls.size(), 1'000'000u);
  EXPECT_EQ(overlappingPairs(scene.balls), 0u);
  EXPECT_NO_THROW(validateScene(scene, "million"));
}

}  // namespace
}  // namespace fooball
