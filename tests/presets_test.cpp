// The built-in scenes: every one loads and is valid, and each shows what its description says.

#include "fooball/presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fooball/scene_file.h"

namespace fooball {
namespace {

/// "Touching" for balls placed from decimal text: a few ulps of a 10 m coordinate.
constexpr double kTouchTolerance = 1e-9;  // m

bool touching(const BallDef& a, const BallDef& b) {
  return std::abs(length(a.position - b.position) - (a.radius + b.radius)) < kTouchTolerance;
}

double packingFraction(const Scene& scene) {
  double area = 0.0;
  for (const BallDef& ball : scene.balls)
    area += std::numbers::pi * ball.radius * ball.radius;
  return area / (scene.box.width * scene.box.height);
}

TEST(Presets, AreTheTenListedInOrder) {
  std::vector<std::string> names;
  for (const Preset& preset : presets())
    names.emplace_back(preset.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"default", "gas", "head-on", "glancing", "cradle",
                                      "billiards", "mass-ratio", "tunnelling", "dense", "rain"}));
}

TEST(Presets, EveryPresetLoadsIsValidAndRoundTrips) {
  for (const Preset& preset : presets()) {
    SCOPED_TRACE(std::string(preset.name));
    EXPECT_FALSE(preset.description.empty());
    EXPECT_EQ(preset.description.find('\n'), std::string_view::npos);
    EXPECT_FALSE(preset.lookFor.empty());
    EXPECT_EQ(findPreset(preset.name), &preset);
    const Scene scene = loadPreset(preset.name);
    EXPECT_FALSE(scene.name.empty());
    EXPECT_FALSE(scene.balls.empty());
    EXPECT_EQ(scene.box, (Box{16.0, 9.0}));
    EXPECT_NO_THROW(validateScene(scene, preset.name));
    EXPECT_EQ(writeScene(parseScene(writeScene(scene), "again")), writeScene(scene));
  }
}

TEST(Presets, DefaultPresetExists) {
  EXPECT_NO_THROW(loadPreset(kDefaultPreset));
}

TEST(Presets, FindPresetReturnsNullForAnUnknownName) {
  EXPECT_EQ(findPreset("pinball"), nullptr);
}

TEST(Presets, UnknownNameListsTheKnownOnes) {
  EXPECT_THROW(
      {
        try {
          loadPreset("pinball");
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(),
                       "preset 'pinball': no such preset (the presets are: default, gas, head-on, "
                       "glancing, cradle, billiards, mass-ratio, tunnelling, dense, rain)");
          throw;
        }
      },
      SceneError);
}

TEST(Presets, DefaultIsALivelyMixOfSizesUnderGravity) {
  const Scene scene = loadPreset("default");
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, -9.81}));
  EXPECT_TRUE(scene.world.walls.allOn());
  EXPECT_TRUE(scene.world.ballCollisions);
  EXPECT_GE(scene.balls.size(), 24u);
  EXPECT_LE(scene.balls.size(), 60u);
  const auto [smallest, biggest] =
      std::minmax_element(scene.balls.begin(), scene.balls.end(),
                          [](const BallDef& a, const BallDef& b) { return a.radius < b.radius; });
  EXPECT_GE(biggest->radius / smallest->radius, 2.0);
  for (const BallDef& ball : scene.balls)
    EXPECT_GT(length(ball.velocity), 0.0);
}

TEST(Presets, GasIsManyEqualBallsAtRandomSpeedsWithoutGravity) {
  const Scene scene = loadPreset("gas");
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
  EXPECT_GE(scene.balls.size(), 200u);
  double slowest = INFINITY;
  double fastest = 0.0;
  for (const BallDef& ball : scene.balls) {
    EXPECT_EQ(ball.radius, scene.balls[0].radius);
    EXPECT_EQ(ball.mass, scene.balls[0].mass);
    slowest = std::min(slowest, length(ball.velocity));
    fastest = std::max(fastest, length(ball.velocity));
  }
  EXPECT_GT(fastest, 2.0 * slowest);
}

TEST(Presets, HeadOnIsTwoEqualBallsApproachingAlongOneLine) {
  const Scene scene = loadPreset("head-on");
  ASSERT_EQ(scene.balls.size(), 2u);
  const BallDef& a = scene.balls[0];
  const BallDef& b = scene.balls[1];
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.position.y, b.position.y);
  EXPECT_EQ(a.velocity, -b.velocity);
  EXPECT_EQ(a.velocity.y, 0.0);
  EXPECT_LT(dot(b.position - a.position, b.velocity - a.velocity), 0.0);  // approaching
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
}

TEST(Presets, GlancingIsAnOffCentreHitOnAnEqualBallAtRest) {
  const Scene scene = loadPreset("glancing");
  ASSERT_EQ(scene.balls.size(), 2u);
  const BallDef& moving = scene.balls[0];
  const BallDef& resting = scene.balls[1];
  EXPECT_EQ(moving.mass, resting.mass);
  EXPECT_EQ(resting.velocity, (Vec2{0.0, 0.0}));
  // Impact parameter: the target's distance from the moving ball's line of motion.
  const Vec2 direction = moving.velocity / length(moving.velocity);
  const Vec2 offset = resting.position - moving.position;
  const double impact = std::abs(offset.x * direction.y - offset.y * direction.x);
  EXPECT_GT(dot(offset, direction), 0.0);
  EXPECT_GT(impact, 0.0);
  EXPECT_LT(impact, moving.radius + resting.radius);
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
}

TEST(Presets, CradleIsARowOfFiveTouchingBallsAndOneMovingIntoThem) {
  const Scene scene = loadPreset("cradle");
  ASSERT_EQ(scene.balls.size(), 6u);
  const BallDef& striker = scene.balls[0];
  for (std::size_t i = 1; i < 6; ++i) {
    const BallDef& ball = scene.balls[i];
    EXPECT_EQ(ball.velocity, (Vec2{0.0, 0.0}));
    EXPECT_EQ(ball.mass, striker.mass);
    EXPECT_EQ(ball.position.y, striker.position.y);
    if (i > 1) {
      EXPECT_TRUE(touching(scene.balls[i - 1], ball)) << i;
    }
  }
  EXPECT_GT(striker.velocity.x, 0.0);
  EXPECT_EQ(striker.velocity.y, 0.0);
  EXPECT_LT(striker.position.x, scene.balls[1].position.x);
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
}

TEST(Presets, BilliardsIsATouchingRackOfFifteenAndAFastCueBall) {
  const Scene scene = loadPreset("billiards");
  ASSERT_EQ(scene.balls.size(), 16u);
  const BallDef& cue = scene.balls[0];
  EXPECT_GE(length(cue.velocity), 5.0);
  for (std::size_t i = 1; i < 16; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(scene.balls[i].velocity, (Vec2{0.0, 0.0}));
    EXPECT_EQ(scene.balls[i].radius, cue.radius);
    std::size_t neighbours = 0;
    for (std::size_t j = 1; j < 16; ++j)
      neighbours += j != i && touching(scene.balls[i], scene.balls[j]) ? 1 : 0;
    EXPECT_GE(neighbours, 2u);  // the corners of a triangle rack touch two, the rest more
  }
  // The cue ball heads for the apex.
  EXPECT_GT(dot(scene.balls[1].position - cue.position, cue.velocity), 0.0);
}

TEST(Presets, MassRatioHasTheLightBallBetweenTheWallAndAHundredTimesHeavierOne) {
  const Scene scene = loadPreset("mass-ratio");
  ASSERT_EQ(scene.balls.size(), 2u);
  const BallDef& light = scene.balls[0];
  const BallDef& heavy = scene.balls[1];
  EXPECT_EQ(heavy.mass / light.mass, 100.0);
  EXPECT_TRUE(scene.world.walls.left);
  EXPECT_LT(light.position.x, heavy.position.x);
  EXPECT_EQ(light.position.y, heavy.position.y);
  EXPECT_EQ(light.velocity, (Vec2{0.0, 0.0}));
  EXPECT_LT(heavy.velocity.x, 0.0);
  EXPECT_EQ(heavy.velocity.y, 0.0);
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
}

TEST(Presets, MassRatioMakesThirtyOneCollisionsTheDigitsOfPi) {
  // Exact 1-D elastic collisions between the wall, the light ball and the heavy one, until the
  // heavy ball moves away faster than the light one follows it.
  const Scene scene = loadPreset("mass-ratio");
  const double light = scene.balls[0].mass;
  const double heavy = scene.balls[1].mass;
  double lightVelocity = scene.balls[0].velocity.x;
  double heavyVelocity = scene.balls[1].velocity.x;
  int collisions = 0;
  for (;;) {
    if (lightVelocity > heavyVelocity) {
      const double centreOfMass = (light * lightVelocity + heavy * heavyVelocity) / (light + heavy);
      lightVelocity = 2.0 * centreOfMass - lightVelocity;
      heavyVelocity = 2.0 * centreOfMass - heavyVelocity;
    } else if (lightVelocity < 0.0) {
      lightVelocity = -lightVelocity;
    } else {
      break;
    }
    ++collisions;
  }
  EXPECT_EQ(collisions, 31);
}

TEST(Presets, TunnellingAimsAFastSmallBallAtAGapNarrowerThanItself) {
  const Scene scene = loadPreset("tunnelling");
  const BallDef& bullet = scene.balls[0];
  EXPECT_GE(length(bullet.velocity), 50.0);
  EXPECT_EQ(bullet.velocity.y, 0.0);
  // The barrier: a column of balls from floor to ceiling, each touching the next but for one
  // gap, which lies on the bullet's line and is narrower than its diameter.
  std::vector<BallDef> barrier(scene.balls.begin() + 1, scene.balls.end());
  std::sort(barrier.begin(), barrier.end(),
            [](const BallDef& a, const BallDef& b) { return a.position.y < b.position.y; });
  EXPECT_NEAR(barrier.front().position.y - barrier.front().radius, 0.0, kTouchTolerance);
  EXPECT_NEAR(barrier.back().position.y + barrier.back().radius, 9.0, kTouchTolerance);
  std::size_t gaps = 0;
  for (std::size_t i = 1; i < barrier.size(); ++i) {
    EXPECT_EQ(barrier[i].position.x, barrier[0].position.x);
    if (touching(barrier[i - 1], barrier[i])) continue;
    ++gaps;
    const double gap = barrier[i].position.y - barrier[i].radius -
                       (barrier[i - 1].position.y + barrier[i - 1].radius);
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, 2.0 * bullet.radius);
    EXPECT_GT(bullet.position.y, barrier[i - 1].position.y + barrier[i - 1].radius);
    EXPECT_LT(bullet.position.y, barrier[i].position.y - barrier[i].radius);
  }
  EXPECT_EQ(gaps, 1u);
  EXPECT_LT(bullet.position.x, barrier[0].position.x);
  EXPECT_GT(bullet.velocity.x, 0.0);
}

TEST(Presets, DenseIsEqualBallsAtTwoThirdsPacking) {
  const Scene scene = loadPreset("dense");
  EXPECT_GE(packingFraction(scene), 0.6);
  EXPECT_LE(packingFraction(scene), 0.7);
  for (const BallDef& ball : scene.balls)
    EXPECT_EQ(ball.radius, scene.balls[0].radius);
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
}

TEST(Presets, RainStartsHighInTheBoxUnderGravityAndAirResistance) {
  const Scene scene = loadPreset("rain");
  EXPECT_LT(scene.world.gravity.y, 0.0);
  EXPECT_GT(scene.world.airResistance, 0.0);  // what lets the pile settle
  EXPECT_GE(scene.balls.size(), 300u);
  for (const BallDef& ball : scene.balls)
    EXPECT_GT(ball.position.y - ball.radius, 0.5 * scene.box.height);
}

}  // namespace
}  // namespace fooball
