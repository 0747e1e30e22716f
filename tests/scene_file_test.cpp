// Scene files: reading, writing, validation and the file boundary. Every rule of the format has
// a test asserting its exact one-line message, "SOURCE: PLACE: REASON", because users and the
// CLI's tests read those lines.

#include "fooball/scene_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "fooball/random_balls.h"

namespace fooball {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The one-line error parseScene gives for `text`, or "(no error)".
std::string errorFrom(std::string_view text) {
  try {
    parseScene(text, "scene.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

/// A valid minimal scene (16 × 9 m box) with `members` added to the top-level object.
std::string sceneWith(std::string_view members = "") {
  std::string text =
      R"({"format": "fooball-scene", "version": 1, "box": {"width": 16, "height": 9}})";
  if (!members.empty()) {
    text.pop_back();
    text += ", ";
    text += members;
    text += "}";
  }
  return text;
}

/// A scene whose balls array holds `balls` (JSON objects, comma-separated).
std::string sceneWithBalls(std::string_view balls) {
  return sceneWith(R"("balls": [)" + std::string(balls) + "]");
}

void expectSameBits(double expected, double actual, std::string_view what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(expected), std::bit_cast<std::uint64_t>(actual))
      << what << ": expected " << expected << ", got " << actual;
}

void expectSameScene(const Scene& expected, const Scene& actual) {
  EXPECT_EQ(expected.name, actual.name);
  expectSameBits(expected.box.width, actual.box.width, "box.width");
  expectSameBits(expected.box.height, actual.box.height, "box.height");
  EXPECT_EQ(expected.world.walls, actual.world.walls);
  expectSameBits(expected.world.gravity.x, actual.world.gravity.x, "gravity.x");
  expectSameBits(expected.world.gravity.y, actual.world.gravity.y, "gravity.y");
  expectSameBits(expected.world.airResistance, actual.world.airResistance, "air_resistance");
  EXPECT_EQ(expected.world.ballCollisions, actual.world.ballCollisions);
  ASSERT_EQ(expected.balls.size(), actual.balls.size());
  for (std::size_t i = 0; i < expected.balls.size(); ++i) {
    const BallDef& e = expected.balls[i];
    const BallDef& a = actual.balls[i];
    const std::string where = "balls[" + std::to_string(i) + "]";
    expectSameBits(e.position.x, a.position.x, where + ".position.x");
    expectSameBits(e.position.y, a.position.y, where + ".position.y");
    expectSameBits(e.velocity.x, a.velocity.x, where + ".velocity.x");
    expectSameBits(e.velocity.y, a.velocity.y, where + ".velocity.y");
    expectSameBits(e.radius, a.radius, where + ".radius");
    expectSameBits(e.mass, a.mass, where + ".mass");
    EXPECT_EQ(e.color, a.color) << where;
    if (::testing::Test::HasFailure()) return;  // one broken ball is enough to read
  }
}

BallDef ballAt(Vec2 position, double radius = 0.5) {
  return {position, {}, radius, diskMass(radius), 0xe0a030};
}

// --- Reading -----------------------------------------------------------------------------------

TEST(SceneFileReading, DesignDocumentExampleParses) {
  const Scene scene = parseScene(R"({
  "format": "fooball-scene",
  "version": 1,
  "name": "Two balls",
  "box": { "width": 16.0, "height": 9.0 },
  "walls": { "left": true, "right": true, "bottom": true, "top": true },
  "gravity": [0.0, -9.81],
  "air_resistance": 0.0,
  "ball_collisions": true,
  "balls": [
    { "position": [2.0, 4.5], "velocity": [3.0, 0.0], "radius": 0.5,
      "mass": 1.0, "color": "#e0a030" }
  ],
  "random_balls": { "count": 200, "radius": [0.1, 0.3], "speed": [0.5, 3.0],
                    "density": 1.0, "seed": 7 }
})",
                                 "scene.json");
  EXPECT_EQ(scene.name, "Two balls");
  EXPECT_EQ(scene.box, (Box{16.0, 9.0}));
  EXPECT_TRUE(scene.world.walls.allOn());
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, -9.81}));
  EXPECT_EQ(scene.world.airResistance, 0.0);
  EXPECT_TRUE(scene.world.ballCollisions);
  ASSERT_EQ(scene.balls.size(), 201u);
  const BallDef& first = scene.balls[0];
  EXPECT_EQ(first.position, (Vec2{2.0, 4.5}));
  EXPECT_EQ(first.velocity, (Vec2{3.0, 0.0}));
  EXPECT_EQ(first.radius, 0.5);
  EXPECT_EQ(first.mass, 1.0);
  EXPECT_EQ(first.color, 0xe0a030u);
  for (std::size_t i = 1; i < scene.balls.size(); ++i) {
    EXPECT_GE(scene.balls[i].radius, 0.1);
    EXPECT_LE(scene.balls[i].radius, 0.3);
  }
}

TEST(SceneFileReading, OnlyFormatVersionAndBoxAreRequiredAndTheRestDefaults) {
  const Scene scene = parseScene(sceneWith(), "scene.json");
  EXPECT_EQ(scene.name, "");
  EXPECT_EQ(scene.box, (Box{16.0, 9.0}));
  EXPECT_TRUE(scene.world.walls.allOn());
  EXPECT_EQ(scene.world.gravity, (Vec2{0.0, 0.0}));
  EXPECT_EQ(scene.world.airResistance, 0.0);
  EXPECT_TRUE(scene.world.ballCollisions);
  EXPECT_TRUE(scene.balls.empty());
  EXPECT_FALSE(scene.dt) << "the default step, kDefaultDt";
}

TEST(SceneFileReading, TheTimeStepIsReadWrittenAndChecked) {
  const Scene scene = parseScene(sceneWith(R"("dt": 0.001)"), "scene.json");
  EXPECT_EQ(scene.dt, std::optional<double>(0.001));
  EXPECT_EQ(parseScene(writeScene(scene), "again.json").dt, std::optional<double>(0.001));
  EXPECT_EQ(writeScene(parseScene(sceneWith(), "scene.json")).find("\"dt\""), std::string::npos)
      << "a scene at the default step is written as before";
  EXPECT_EQ(errorFrom(sceneWith(R"("dt": 0)")), "scene.json: dt: must be > 0 (got 0)");
  EXPECT_EQ(errorFrom(sceneWith(R"("dt": -0.01)")), "scene.json: dt: must be > 0 (got -0.01)");
  EXPECT_EQ(errorFrom(sceneWith(R"("dt": "fast")")).rfind("scene.json: dt: must be a number", 0),
            0u)
      << errorFrom(sceneWith(R"("dt": "fast")"));
}

TEST(SceneFileReading, BallNeedsPositionAndRadiusOnlyVelocityMassAndColorDefault) {
  const Scene scene = parseScene(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                                   {"position": [6, 2], "radius": 0.25})"),
                                 "scene.json");
  ASSERT_EQ(scene.balls.size(), 2u);
  EXPECT_EQ(scene.balls[0].velocity, (Vec2{0.0, 0.0}));
  EXPECT_EQ(scene.balls[0].mass, std::numbers::pi * 0.25);  // 1 kg/m² × π r²
  EXPECT_EQ(scene.balls[1].mass, std::numbers::pi * 0.0625);
  EXPECT_EQ(scene.balls[0].color, defaultBallColor(0));
  EXPECT_EQ(scene.balls[1].color, defaultBallColor(1));
}

TEST(SceneFileReading, ColorHexDigitsMayBeEitherCase) {
  const Scene scene = parseScene(
      sceneWithBalls(R"({"position": [2, 2], "radius": 0.5, "color": "#E0a03F"})"), "scene.json");
  EXPECT_EQ(scene.balls[0].color, 0xe0a03fu);
}

TEST(SceneFileReading, WallsMissingFromTheObjectStayOn) {
  const Scene scene = parseScene(sceneWith(R"("walls": {"top": false})"), "scene.json");
  EXPECT_EQ(scene.world.walls, (Walls{true, true, true, false}));
}

TEST(SceneFileReading, RandomBallsFollowTheExplicitBallsAndContinueTheirColors) {
  const Scene scene = parseScene(sceneWith(R"("balls": [{"position": [8, 4.5], "radius": 1}],
                   "random_balls": {"count": 50, "radius": [0.1, 0.2], "speed": [1, 2]})"),
                                 "scene.json");
  ASSERT_EQ(scene.balls.size(), 51u);
  EXPECT_EQ(scene.balls[0].position, (Vec2{8.0, 4.5}));
  EXPECT_EQ(scene.balls[50].color, defaultBallColor(50));
}

TEST(SceneFileReading, RandomBallsDefaultToDensityOneAndSeedOne) {
  const Scene fromFile = parseScene(
      sceneWith(R"("random_balls": {"count": 20, "radius": [0.1, 0.2], "speed": [1, 2]})"),
      "scene.json");
  Scene expected = parseScene(sceneWith(), "scene.json");
  addRandomBalls(expected, {20, 0.1, 0.2, 1.0, 2.0, 1.0, 1});
  expectSameScene(expected, fromFile);
}

// --- Writing and the round trip ----------------------------------------------------------------

Scene awkwardScene() {
  Scene scene;
  scene.name = "Ünïcode \"quotes\" \\ and\nnewline";
  scene.box = {1.0 / 3.0, 0.1 + 0.2};
  scene.world.walls = {false, true, false, true};
  scene.world.gravity = {-0.0, -9.81};
  scene.world.airResistance = std::nextafter(0.5, 1.0);
  scene.world.ballCollisions = false;
  scene.balls = {
      {{0.1, 0.1}, {5e-324, -1e300}, 0.1, std::numeric_limits<double>::min(), 0x000000},
      {{-1e6, -12345.678901234567}, {-0.0, 0.0}, 1e-9, 1e300, 0xffffff},
      {{0.2, 0.15}, {1.0 / 7.0, 2.0 / 3.0}, 0.05, 123456789012.0, 0x123abc},
  };
  return scene;
}

TEST(SceneFileWriting, ParseOfWriteReproducesEveryDoubleBitForBit) {
  const Scene scene = awkwardScene();
  expectSameScene(scene, parseScene(writeScene(scene), "written"));
}

TEST(SceneFileWriting, RandomTenThousandBallSceneRoundTripsBitForBit) {
  Scene scene = parseScene(sceneWith(R"("gravity": [0.3, -9.81], "air_resistance": 0.01)"), "x");
  addRandomBalls(scene, {10'000, 0.01, 0.05, 0.1, 7.0, 2.5, 42});
  expectSameScene(scene, parseScene(writeScene(scene), "written"));
}

TEST(SceneFileWriting, WritesEveryKeyAndOneBallPerLine) {
  Scene scene;
  scene.name = "two";
  scene.balls = {ballAt({2.0, 2.0}), ballAt({6.0, 2.0})};
  EXPECT_EQ(writeScene(scene), R"({
  "format": "fooball-scene",
  "version": 1,
  "name": "two",
  "box": {"width": 16.0, "height": 9.0},
  "walls": {"left": true, "right": true, "bottom": true, "top": true},
  "gravity": [0.0, 0.0],
  "air_resistance": 0.0,
  "ball_collisions": true,
  "balls": [
    {"position": [2.0, 2.0], "velocity": [0.0, 0.0], "radius": 0.5, "mass": 0.7853981633974483, "color": "#e0a030"},
    {"position": [6.0, 2.0], "velocity": [0.0, 0.0], "radius": 0.5, "mass": 0.7853981633974483, "color": "#e0a030"}
  ]
}
)");
}

TEST(SceneFileWriting, EmptySceneWritesAnEmptyBallsArray) {
  const std::string text = writeScene(Scene{});
  EXPECT_NE(text.find(R"("balls": [])"), std::string::npos) << text;
  EXPECT_TRUE(parseScene(text, "written").balls.empty());
}

TEST(SceneFileWriting, StateWithWallsOffAndBallsOutsideLoadsBack) {
  Scene scene;
  scene.world.walls = {false, false, false, false};
  scene.balls = {ballAt({-100.0, 4.0}), ballAt({40.0, -3.0}), ballAt({8.0, 1e9})};
  expectSameScene(scene, parseScene(writeScene(scene), "written"));
}

TEST(SceneFileWriting, RefusesNumbersJsonCannotHold) {
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0}), ballAt({kNaN, 2.0})};
  EXPECT_THROW(
      {
        try {
          writeScene(scene);
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(), "balls[1].position[0]: cannot be written: JSON has no nan");
          throw;
        }
      },
      SceneError);
}

TEST(SceneFileWriting, RefusesColorsWiderThan24Bits) {
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0})};
  scene.balls[0].color = 0x1000000;
  EXPECT_THROW(writeScene(scene), SceneError);
}

// --- Errors: format, version, keys -------------------------------------------------------------

TEST(SceneFileErrors, TopLevelMustBeAnObject) {
  EXPECT_EQ(errorFrom("[1, 2]"),
            "scene.json: a scene must be a JSON object (got an array of 2 elements)");
}

TEST(SceneFileErrors, FormatIsRequired) {
  EXPECT_EQ(errorFrom(R"({"version": 1, "box": {"width": 16, "height": 9}})"),
            R"(scene.json: missing required key "format")");
}

TEST(SceneFileErrors, FormatMustBeFooballScene) {
  EXPECT_EQ(errorFrom(R"({"format": "foo-scene", "version": 1})"),
            R"(scene.json: format: must be "fooball-scene" (got the string "foo-scene"))");
}

TEST(SceneFileErrors, VersionIsRequired) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "box": {"width": 16, "height": 9}})"),
            R"(scene.json: missing required key "version")");
}

TEST(SceneFileErrors, OtherVersionsAreUnsupported) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 2})"),
            "scene.json: version: unsupported version 2 (this build reads version 1)");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": -1})"),
            "scene.json: version: unsupported version -1 (this build reads version 1)");
}

TEST(SceneFileErrors, VersionMustBeAnInteger) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1.0})"),
            "scene.json: version: must be the integer 1 (got the number 1.0)");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": "1"})"),
            R"(scene.json: version: must be the integer 1 (got the string "1"))");
}

TEST(SceneFileErrors, VersionIsCheckedBeforeUnknownKeys) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 2, "springs": []})"),
            "scene.json: version: unsupported version 2 (this build reads version 1)");
}

TEST(SceneFileErrors, UnknownTopLevelKeyIsNamedWithTheKnownKeys) {
  EXPECT_EQ(errorFrom(sceneWith(R"("gravty": [0, -9.81])")),
            R"(scene.json: unknown key "gravty" (known keys: format, version, name, box, walls, )"
            R"(gravity, air_resistance, ball_collisions, dt, balls, random_balls, saved_from))");
}

TEST(SceneFileErrors, UnknownKeysInNestedObjectsAreNamed) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": 16, "height": 9, "depth": 3}})"),
            R"(scene.json: box: unknown key "depth" (known keys: width, height))");
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"front": true})")),
            R"(scene.json: walls: unknown key "front" (known keys: left, right, bottom, top))");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [5, 2], "radius": 0.5, "spin": 1})")),
            R"(scene.json: balls[1]: unknown key "spin" )"
            R"((known keys: position, velocity, radius, mass, color))");
  EXPECT_EQ(
      errorFrom(sceneWith(
          R"("random_balls": {"count": 1, "radius": [1, 1], "speed": [1, 1], "colour": "#fff"})")),
      R"(scene.json: random_balls: unknown key "colour" )"
      R"((known keys: count, radius, speed, density, seed))");
}

TEST(SceneFileErrors, RepeatedKeyIsAnErrorNotLastOneWins) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1, "version": 1})"),
            R"(scene.json: duplicate key "version")");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [5, 2], "radius": 0.5, "radius": 1})")),
            R"(scene.json: balls[1]: duplicate key "radius")");
}

TEST(SceneFileErrors, UnknownKeysAreShownPrintable) {
  EXPECT_EQ(errorFrom(sceneWith("\"a\\u0001b\": 1")),
            R"(scene.json: unknown key "a\x01b" (known keys: format, version, name, box, walls, )"
            R"(gravity, air_resistance, ball_collisions, dt, balls, random_balls, saved_from))");
}

// --- Errors: JSON types ------------------------------------------------------------------------

TEST(SceneFileErrors, BoxIsRequiredWithWidthAndHeight) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1})"),
            R"(scene.json: missing required key "box")");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1, "box": {"width": 16}})"),
            R"(scene.json: box: missing required key "height")");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1, "box": [16, 9]})"),
            "scene.json: box: must be an object (got an array of 2 elements)");
}

TEST(SceneFileErrors, WrongTypeNamesExpectedAndActual) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": "16", "height": 9}})"),
            R"(scene.json: box.width: must be a number (got the string "16"))");
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"left": 1})")),
            "scene.json: walls.left: must be true or false (got the number 1)");
  EXPECT_EQ(errorFrom(sceneWith(R"("ball_collisions": "yes")")),
            R"(scene.json: ball_collisions: must be true or false (got the string "yes"))");
  EXPECT_EQ(errorFrom(sceneWith(R"("air_resistance": null)")),
            "scene.json: air_resistance: must be a number (got null)");
  EXPECT_EQ(errorFrom(sceneWith(R"("name": 7)")),
            "scene.json: name: must be a string (got the number 7)");
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": true)")),
            "scene.json: walls: must be an object (got true)");
}

TEST(SceneFileErrors, VectorsMustBeTwoNumbers) {
  EXPECT_EQ(errorFrom(sceneWith(R"("gravity": -9.81)")),
            "scene.json: gravity: must be [x, y] (got the number -9.81)");
  EXPECT_EQ(errorFrom(sceneWith(R"("gravity": [0, -9.81, 0])")),
            "scene.json: gravity: must be [x, y] (got an array of 3 elements)");
  EXPECT_EQ(errorFrom(sceneWith(R"("gravity": [0, null])")),
            "scene.json: gravity[1]: must be a number (got null)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "velocity": {"x": 1}, "radius": 1})")),
            "scene.json: balls[0].velocity: must be [x, y] (got an object)");
}

TEST(SceneFileErrors, BallsMustBeAnArrayOfObjects) {
  EXPECT_EQ(errorFrom(sceneWith(R"("balls": {"position": [2, 2]})")),
            "scene.json: balls: must be an array (got an object)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5}, 3)")),
            "scene.json: balls[1]: must be an object (got the number 3)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"([2, 2])")),
            "scene.json: balls[0]: must be an object (got an array of 2 elements)");
}

TEST(SceneFileErrors, BallNeedsPositionAndRadius) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"radius": 0.5})")),
            R"(scene.json: balls[0]: missing required key "position")");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2]})")),
            R"(scene.json: balls[0]: missing required key "radius")");
}

TEST(SceneFileErrors, ColorMustBeHashAndSixHexDigits) {
  for (const char* color :
       {R"("red")", R"("e0a030")", R"("#e0a03")", R"("#e0a0300")", R"("#e0a03g")"}) {
    EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5, "color": )" +
                                       std::string(color) + "}")),
              "scene.json: balls[0].color: must be a colour \"#rrggbb\" (got the string " +
                  std::string(color) + ")");
  }
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5, "color": 14721072})")),
            "scene.json: balls[0].color: must be a colour \"#rrggbb\" (got the number 14721072)");
}

TEST(SceneFileErrors, BallErrorsComeAfterFormatAndVersionWhateverTheKeyOrder) {
  EXPECT_EQ(errorFrom(R"({"balls": [{"radius": 1}], "format": "fooball-scene", "version": 3})"),
            "scene.json: version: unsupported version 3 (this build reads version 1)");
}

TEST(SceneFileErrors, FirstBadBallIsReported) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [4, 2]},
                                        {"position": "x", "radius": 0.5})")),
            R"(scene.json: balls[1]: missing required key "radius")");
}

// --- Errors: numbers ---------------------------------------------------------------------------

TEST(SceneFileErrors, NumbersBeyondDoubleRangeAreNamedAtTheirPlace) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [4, 2], "radius": 1e999})")),
            "scene.json: balls[1].radius: the number 1e999 is beyond the range of a double");
  EXPECT_EQ(errorFrom(sceneWith(R"("gravity": [0, -1e400])")),
            "scene.json: gravity[1]: the number -1e400 is beyond the range of a double");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": 1e309, "height": 9}})"),
            "scene.json: box.width: the number 1e309 is beyond the range of a double");
}

TEST(SceneFileErrors, BoxSidesMustBePositive) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": -1, "height": 9}})"),
            "scene.json: box.width: must be > 0 (got -1)");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": 16, "height": 0}})"),
            "scene.json: box.height: must be > 0 (got 0)");
}

TEST(SceneFileErrors, BoxSidesHaveAStatedLimit) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": 16, "height": 1000000.5}})"),
            "scene.json: box.height: must be at most 1000000 m (got 1000000.5)");
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1,
                          "box": {"width": 1000000, "height": 1000000}})"),
            "(no error)");
}

TEST(SceneFileErrors, RadiusMustBePositive) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [1, 1], "radius": 0.5},
                                        {"position": [3, 1], "radius": 0.5},
                                        {"position": [5, 1], "radius": 0.5},
                                        {"position": [7, 1], "radius": -1})")),
            "scene.json: balls[3].radius: must be > 0 (got -1)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [1, 1], "radius": 0})")),
            "scene.json: balls[0].radius: must be > 0 (got 0)");
}

TEST(SceneFileErrors, RadiusHasTheBoxSideAsLimit) {
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"left": false, "right": false, "bottom": false,
                                             "top": false},
                                   "balls": [{"position": [1, 1], "radius": 2e6}])")),
            "scene.json: balls[0].radius: must be at most 1000000 m (got 2e+06)");
}

TEST(SceneFileErrors, MassMustBePositive) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [1, 1], "radius": 0.5, "mass": 0})")),
            "scene.json: balls[0].mass: must be > 0 (got 0)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [1, 1], "radius": 0.5, "mass": -2.5})")),
            "scene.json: balls[0].mass: must be > 0 (got -2.5)");
}

TEST(SceneFileErrors, AirResistanceMustNotBeNegative) {
  EXPECT_EQ(errorFrom(sceneWith(R"("air_resistance": -0.5)")),
            "scene.json: air_resistance: must be >= 0 (got -0.5)");
}

TEST(SceneFileErrors, EmptyAndWhitespaceTextAreInvalidJson) {
  EXPECT_EQ(errorFrom(""), "scene.json: invalid JSON: the text is empty");
  EXPECT_EQ(errorFrom(" \n\t "), "scene.json: invalid JSON: the text is empty");
}

TEST(SceneFileErrors, SyntaxErrorNamesLineAndColumn) {
  EXPECT_EQ(errorFrom("{\n  \"format\": \"fooball-scene\",\n  \"version\": x\n}"),
            "scene.json: invalid JSON at line 3, column 14: syntax error while parsing value - "
            "invalid literal; last read: '\"version\": x'");
}

TEST(SceneFileErrors, TruncatedJsonIsInvalidAtItsEnd) {
  EXPECT_EQ(errorFrom(R"({"format": "fooball-scene", "version": 1, "box": {"width)"),
            "scene.json: invalid JSON at line 1, column 57: syntax error while parsing object "
            "key - invalid string: missing closing quote; last read: '\"width'; expected string "
            "literal");
}

TEST(SceneFileErrors, TrailingTextIsInvalidJson) {
  EXPECT_EQ(errorFrom(sceneWith() + " {}"),
            "scene.json: invalid JSON at line 1, column 78: syntax error while parsing value - "
            "unexpected '{'; expected end of input");
}

TEST(SceneFileErrors, BinaryBytesGiveOnePrintableLine) {
  const std::string garbage("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\xff\xfe", 19);
  const std::string message = errorFrom(garbage);
  EXPECT_EQ(message,
            "scene.json: invalid JSON at line 1, column 1: syntax error while parsing value - "
            "invalid literal; last read: '\\x89'");
  for (const char c : message)
    EXPECT_TRUE(c >= 0x20 && c < 0x7f) << message;
}

TEST(SceneFileErrors, InvalidUtf8InAStringIsInvalidJson) {
  EXPECT_EQ(errorFrom(sceneWith("\"name\": \"caf\xe9\"")),
            "scene.json: invalid JSON at line 1, column 91: syntax error while parsing value - "
            "invalid string: ill-formed UTF-8 byte; last read: '\"caf\\xe9\"'");
}

TEST(SceneFileErrors, NestingDeeperThanTheLimitIsRefusedBeforeParsing) {
  const std::string megabyteOfBrackets(1 << 20, '[');
  EXPECT_EQ(errorFrom(megabyteOfBrackets),
            "scene.json: invalid JSON at line 1, column 65: nested more than 64 levels deep");
  EXPECT_EQ(errorFrom(sceneWith(R"("name": )" + std::string(100, '{'))),
            "scene.json: invalid JSON at line 1, column 149: nested more than 64 levels deep");
}

TEST(SceneFileErrors, BracketsInsideStringsDoNotCountAsNesting) {
  const std::string name = std::string(100, '[') + "\\\"{{" + std::string(100, '{');
  EXPECT_EQ(parseScene(sceneWith(R"("name": ")" + name + "\""), "scene.json").name,
            std::string(100, '[') + "\"{{" + std::string(100, '{'));
}

// --- Errors: balls inside the box and apart ----------------------------------------------------

TEST(SceneFileErrors, BallMustNotCrossAWallThatIsOn) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [0.2, 4], "radius": 0.5})")),
            "scene.json: balls[0].position: the ball crosses the left wall by 0.3 m, more than 5% "
            "of its radius");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [16, 4], "radius": 0.5})")),
            "scene.json: balls[0].position: the ball crosses the right wall by 0.5 m, more than "
            "5% of its radius");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [8, -3], "radius": 0.5})")),
            "scene.json: balls[0].position: the ball crosses the bottom wall by 3.5 m, more than "
            "5% of its radius");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [8, 8.6], "radius": 0.5})")),
            "scene.json: balls[0].position: the ball crosses the top wall by 0.1 m, more than 5% "
            "of its radius");
}

TEST(SceneFileErrors, BallMayTouchAWallUpToTheContactSlop) {
  // 0.02 m past the wall is 4% of a 0.5 m radius: a contact a time-stepped solver leaves.
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [0.48, 4], "radius": 0.5},
                                        {"position": [15.52, 4], "radius": 0.5})")),
            "(no error)");
}

TEST(SceneFileErrors, BallMayLieAnywhereBeyondAWallThatIsOff) {
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"left": false, "top": false},
                                   "balls": [{"position": [-500, 4], "radius": 0.5},
                                             {"position": [8, 1e12], "radius": 0.5}])")),
            "(no error)");
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"left": false},
                                   "balls": [{"position": [-500, -4], "radius": 0.5}])")),
            "scene.json: balls[0].position: the ball crosses the bottom wall by 4.5 m, more than "
            "5% of its radius");
}

TEST(SceneFileErrors, OverlapNamesBothBallsAndTheDepth) {
  // balls[3] and balls[7] are 0.94 m apart with radii 0.5: 0.06 m deep, 12% of the radius.
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [1, 1], "radius": 0.5},
                                        {"position": [3, 1], "radius": 0.5},
                                        {"position": [5, 1], "radius": 0.5},
                                        {"position": [5, 4.5], "radius": 0.5},
                                        {"position": [7, 1], "radius": 0.5},
                                        {"position": [9, 1], "radius": 0.5},
                                        {"position": [11, 1], "radius": 0.5},
                                        {"position": [5.94, 4.5], "radius": 0.5})")),
            "scene.json: balls[7]: overlaps balls[3] by 12% of the smaller radius (the limit is "
            "5%)");
}

TEST(SceneFileErrors, OverlapIsMeasuredAgainstTheSmallerRadius) {
  // A 0.1 m ball 0.02 m deep into a 2 m ball: 20% of the smaller radius.
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [8, 4.5], "radius": 2},
                                        {"position": [10.08, 4.5], "radius": 0.1})")),
            "scene.json: balls[1]: overlaps balls[0] by 20% of the smaller radius (the limit is "
            "5%)");
}

TEST(SceneFileErrors, TouchingAndSlightlyOverlappingBallsAreValid) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [3, 2], "radius": 0.5},
                                        {"position": [3.98, 2], "radius": 0.5})")),
            "(no error)");
}

TEST(SceneFileErrors, OverlapIsAllowedWhileBallCollisionsAreOff) {
  EXPECT_EQ(errorFrom(sceneWith(R"("ball_collisions": false,
                                   "balls": [{"position": [2, 2], "radius": 0.5},
                                             {"position": [2, 2], "radius": 0.5}])")),
            "(no error)");
}

TEST(SceneFileErrors, OverlapIsFoundBeyondWallsThatAreOff) {
  EXPECT_EQ(errorFrom(sceneWith(R"("walls": {"left": false, "right": false},
                                   "balls": [{"position": [-1e9, 2], "radius": 0.5},
                                             {"position": [-1e9, 2.5], "radius": 0.5}])")),
            "scene.json: balls[1]: overlaps balls[0] by 100% of the smaller radius (the limit is "
            "5%)");
}

// --- Errors: counts and random_balls -----------------------------------------------------------

TEST(SceneFileErrors, RandomBallCountHasAStatedLimit) {
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 2000001, "radius": [0.1, 0.1], "speed": [1, 1]})")),
            "scene.json: random_balls.count: must be at most 2000000 (got 2000001)");
}

TEST(SceneFileErrors, ExplicitAndRandomBallsTogetherHaveTheSameLimit) {
  EXPECT_EQ(
      errorFrom(sceneWith(R"("balls": [{"position": [2, 2], "radius": 0.5},
                                       {"position": [4, 2], "radius": 0.5}],
                             "random_balls": {"count": 1999999, "radius": [0.1, 0.1],
                                              "speed": [1, 1]})")),
      "scene.json: random_balls.count: 1999999 random balls and 2 explicit balls are more than "
      "the limit of 2000000");
}

TEST(SceneFileErrors, BallsArrayHasAStatedLimit) {
  // The limit outranks what the elements hold, so the cheapest elements do.
  std::string elements;
  for (std::size_t i = 0; i <= kMaxBalls; ++i)
    elements += "0,";
  elements.pop_back();
  EXPECT_EQ(errorFrom(sceneWithBalls(elements)),
            "scene.json: balls: has more than 2000000 balls (the limit)");
}

TEST(SceneFileErrors, RandomBallsNeedCountRadiusAndSpeed) {
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"radius": [0.1, 0.2], "speed": [1, 2]})")),
            R"(scene.json: random_balls: missing required key "count")");
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 5, "speed": [1, 2]})")),
            R"(scene.json: random_balls: missing required key "radius")");
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 5, "radius": [0.1, 0.2]})")),
            R"(scene.json: random_balls: missing required key "speed")");
}

TEST(SceneFileErrors, RandomBallCountAndSeedAreWholeNumbersAtLeastZero) {
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": -1, "radius": [0.1, 0.2], "speed": [1, 2]})")),
            "scene.json: random_balls.count: must be >= 0 (got -1)");
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 2.5, "radius": [0.1, 0.2], "speed": [1, 2]})")),
            "scene.json: random_balls.count: must be a whole number (got the number 2.5)");
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 1, "radius": [0.1, 0.2],
                                                    "speed": [1, 2], "seed": -7})")),
            "scene.json: random_balls.seed: must be >= 0 (got -7)");
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 1, "radius": [0.1, 0.2],
                                                    "speed": [1, 2],
                                                    "seed": 18446744073709551615})")),
            "(no error)");
}

TEST(SceneFileErrors, RandomBallRangesMustBeMinMaxInOrder) {
  EXPECT_EQ(
      errorFrom(sceneWith(R"("random_balls": {"count": 5, "radius": [0, 0.3], "speed": [1, 2]})")),
      "scene.json: random_balls.radius: must be [min, max] with 0 < min <= max (got [0, "
      "0.3])");
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 5, "radius": [0.3, 0.1], "speed": [1, 2]})")),
            "scene.json: random_balls.radius: must be [min, max] with 0 < min <= max (got [0.3, "
            "0.1])");
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 5, "radius": [0.1, 0.3], "speed": [-1, 2]})")),
            "scene.json: random_balls.speed: must be [min, max] with 0 <= min <= max (got [-1, "
            "2])");
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 5, "radius": [0.1, 0.3], "speed": [3, 2]})")),
            "scene.json: random_balls.speed: must be [min, max] with 0 <= min <= max (got [3, "
            "2])");
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 5, "radius": 0.3, "speed": [1, 2]})")),
            "scene.json: random_balls.radius: must be [min, max] (got the number 0.3)");
}

TEST(SceneFileErrors, RandomBallDensityMustBePositive) {
  EXPECT_EQ(errorFrom(sceneWith(R"("random_balls": {"count": 5, "radius": [0.1, 0.3],
                                                    "speed": [1, 2], "density": 0})")),
            "scene.json: random_balls.density: must be > 0 (got 0)");
}

TEST(SceneFileErrors, RandomBallsAreCheckedEvenWhenCountIsZero) {
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 0, "radius": [0.3, 0.1], "speed": [1, 2]})")),
            "scene.json: random_balls.radius: must be [min, max] with 0 < min <= max (got [0.3, "
            "0.1])");
}

TEST(SceneFileErrors, RandomBallsThatCannotFitSayHowManyCan) {
  EXPECT_EQ(errorFrom(sceneWith(
                R"("random_balls": {"count": 5000, "radius": [0.1, 0.3], "speed": [1, 2]})")),
            "scene.json: random_balls.count: 5000 balls of radius up to 0.3 m do not fit: the box "
            "has room for at most 390");
}

// --- Validating in-memory scenes ---------------------------------------------------------------

TEST(SceneValidation, ValidateSceneNamesTheSourceAndPlace) {
  Scene scene;
  scene.world.gravity = {kNaN, -9.81};
  EXPECT_THROW(
      {
        try {
          validateScene(scene, "saved state");
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(), "saved state: gravity[0]: must be finite (got nan)");
          throw;
        }
      },
      SceneError);
}

std::string validationError(const Scene& scene) {
  try {
    validateScene(scene, "state");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(SceneValidation, RejectsNonFiniteBallValues) {
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0})};
  scene.balls[0].velocity.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validationError(scene), "state: balls[0].velocity[1]: must be finite (got inf)");
  scene.balls[0] = ballAt({2.0, 2.0});
  scene.balls[0].mass = kNaN;
  EXPECT_EQ(validationError(scene), "state: balls[0].mass: must be finite (got nan)");
  scene.balls[0] = ballAt({2.0, 2.0});
  scene.world.airResistance = kNaN;
  EXPECT_EQ(validationError(scene), "state: air_resistance: must be finite (got nan)");
}

TEST(SceneValidation, RejectsColorsWiderThan24Bits) {
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0})};
  scene.balls[0].color = 0x1000000;
  EXPECT_EQ(validationError(scene), "state: balls[0].color: must be 0xRRGGBB (got 0x1000000)");
}

TEST(SceneValidation, RejectsMoreThanTheBallLimit) {
  Scene scene;
  scene.world.ballCollisions = false;
  scene.balls.assign(kMaxBalls + 1, ballAt({2.0, 2.0}));
  EXPECT_EQ(validationError(scene),
            "state: balls: has 2000001 balls, more than the limit of 2000000");
}

TEST(SceneValidation, FindsAnOverlapAmongManySmallBallsAroundBigOnes) {
  // Sizes from 1 mm to 2 m: one grid sized for the biggest ball would be quadratic here.
  Scene scene;
  scene.box = {100.0, 100.0};
  scene.balls = {ballAt({20.0, 20.0}, 2.0), ballAt({70.0, 70.0}, 2.0)};
  addRandomBalls(scene, {100'000, 0.001, 0.05, 0.0, 1.0, 1.0, 3});
  EXPECT_EQ(validationError(scene), "(no error)");
  const std::size_t last = scene.balls.size();
  scene.balls.push_back(ballAt({70.0 + 2.0 + 0.001 - 0.0005, 70.0}, 0.001));
  EXPECT_EQ(validationError(scene), "state: balls[" + std::to_string(last) +
                                        "]: overlaps balls[1] by 50% of the smaller radius "
                                        "(the limit is 5%)");
}

TEST(SceneValidation, ValidateBallHoldsTheBallInsideTheWallsThatAreOn) {
  const Box box;
  EXPECT_NO_THROW(validateBall(ballAt({8.0, 4.5}), box, Walls{}, "balls[3]"));
  EXPECT_THROW(
      {
        try {
          validateBall({{8.0, 4.5}, {}, -1.0, 1.0, 0}, box, Walls{}, "balls[3]");
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(), "balls[3].radius: must be > 0 (got -1)");
          throw;
        }
      },
      SceneError);
  EXPECT_THROW(
      {
        try {
          validateBall(ballAt({8.0, 10.0}), box, Walls{}, "balls[3]");
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(),
                       "balls[3].position: the ball crosses the top wall by 1.5 m, more than 5% "
                       "of its radius");
          throw;
        }
      },
      SceneError);
  Walls topOff;
  topOff.top = false;
  EXPECT_NO_THROW(validateBall(ballAt({8.0, 10.0}), box, topOff, "balls[3]"));
}

// --- States saved from a running simulation (saved_from) ---------------------------------------

constexpr std::string_view kSavedFrom =
    R"("saved_from": {"backend": "elastic", "options": {"substeps": 4}, "time": 12.5})";

/// A scene with saved_from whose balls are `balls` (JSON objects, comma-separated).
std::string savedSceneWithBalls(std::string_view balls) {
  return sceneWith(std::string(kSavedFrom) + R"(, "balls": [)" + std::string(balls) + "]");
}

/// The warning savedStateWarning gives for the scene `text` holds, or "(no warning)".
std::string warningFor(std::string_view text) {
  const std::string warning = savedStateWarning(parseScene(text, "scene.json"), "scene.json");
  return warning.empty() ? "(no warning)" : warning;
}

/// What the app saves: a state with every kind of value and saved_from.
Scene savedState() {
  Scene scene = awkwardScene();
  scene.world.ballCollisions = true;
  scene.world.walls = Walls{};
  scene.savedFrom = SavedFrom{"box2d", {{"substeps", 8.0}, {"bullets", 0.0}, {"scale", 0.1}}, 1.25};
  return scene;
}

TEST(SavedStates, DesignDocumentExampleParses) {
  const Scene scene = parseScene(sceneWith(kSavedFrom), "scene.json");
  ASSERT_TRUE(scene.savedFrom.has_value());
  EXPECT_EQ(*scene.savedFrom, (SavedFrom{"elastic", {{"substeps", 4.0}}, 12.5}));
}

TEST(SavedStates, HandWrittenScenesHaveNoSavedFrom) {
  EXPECT_FALSE(parseScene(sceneWith(), "scene.json").savedFrom.has_value());
  EXPECT_EQ(writeScene(parseScene(sceneWith(), "scene.json")).find("saved_from"),
            std::string::npos);
}

TEST(SavedStates, OptionsMayBeLeftOut) {
  const Scene scene =
      parseScene(sceneWith(R"("saved_from": {"backend": "exact", "time": 0})"), "scene.json");
  ASSERT_TRUE(scene.savedFrom.has_value());
  EXPECT_TRUE(scene.savedFrom->options.empty());
  EXPECT_EQ(scene.savedFrom->backend, "exact");
}

TEST(SavedStates, WritesSavedFromBeforeTheBallsWithOptionsByName) {
  Scene scene;
  scene.savedFrom = SavedFrom{"elastic", {{"threads", 2.0}, {"substeps", 4.0}}, 12.5};
  const std::string text = writeScene(scene);
  EXPECT_NE(text.find("  \"ball_collisions\": true,\n  \"saved_from\": {\"backend\": \"elastic\", "
                      "\"options\": {\"substeps\": 4, \"threads\": 2}, \"time\": 12.5},\n  "
                      "\"balls\": []"),
            std::string::npos)
      << text;
}

TEST(SavedStates, WriteReadWriteGivesTheSameBytesAndEveryBit) {
  const Scene scene = savedState();
  const std::string written = writeScene(scene);
  const Scene read = parseScene(written, "written");
  expectSameScene(scene, read);
  ASSERT_TRUE(read.savedFrom.has_value());
  EXPECT_EQ(*read.savedFrom, *scene.savedFrom);
  EXPECT_EQ(writeScene(read), written);
}

TEST(SavedStates, OptionValuesKeepEveryBitIncludingTheSignOfZero) {
  Scene scene;
  scene.savedFrom =
      SavedFrom{"x", {{"a", -0.0}, {"b", 1e300}, {"c", 5e-324}, {"d", 1.0 / 3.0}, {"e", -7.0}}, 0};
  const Scene read = parseScene(writeScene(scene), "written");
  ASSERT_TRUE(read.savedFrom.has_value());
  for (const auto& [name, value] : scene.savedFrom->options)
    expectSameBits(value, read.savedFrom->options.at(name), name);
  EXPECT_EQ(writeScene(read), writeScene(scene));
}

TEST(SavedStates, OverlappingBallsOpenWithAWarningNamingTheDeepestPair) {
  // balls[1] and balls[0]: 0.06 m deep, 12%; balls[3] and balls[2]: 0.03 m, 6%.
  const std::string text = savedSceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                                  {"position": [2.94, 2], "radius": 0.5},
                                                  {"position": [6, 2], "radius": 0.5},
                                                  {"position": [6.97, 2], "radius": 0.5})");
  const Scene scene = parseScene(text, "scene.json");
  EXPECT_EQ(scene.balls[1].position, (Vec2{2.94, 2.0}));
  EXPECT_EQ(warningFor(text),
            "scene.json: saved from a running simulation: balls[1] overlaps balls[0] by 12% of "
            "the smaller radius");
}

TEST(SavedStates, BallsPressedIntoOrPastAWallOpenWithAWarning) {
  EXPECT_EQ(warningFor(savedSceneWithBalls(R"({"position": [8, 0.4], "radius": 0.5},
                                              {"position": [0.45, 4], "radius": 0.5})")),
            "scene.json: saved from a running simulation: balls[0] crosses the bottom wall by "
            "0.1 m, 20% of its radius");
  EXPECT_EQ(warningFor(savedSceneWithBalls(R"({"position": [8, -3], "radius": 0.5})")),
            "scene.json: saved from a running simulation: balls[0] crosses the bottom wall by "
            "3.5 m, 700% of its radius");
}

TEST(SavedStates, TheWorstCaseIsTheDeepestOfWallsAndPairs) {
  const std::string wall = R"({"position": [8, 0.4], "radius": 0.5})";  // 20% past the wall
  EXPECT_EQ(warningFor(savedSceneWithBalls(wall + R"(, {"position": [2, 2], "radius": 0.5},
                                                      {"position": [2.94, 2], "radius": 0.5})")),
            "scene.json: saved from a running simulation: balls[0] crosses the bottom wall by "
            "0.1 m, 20% of its radius");
  EXPECT_EQ(warningFor(savedSceneWithBalls(wall + R"(, {"position": [2, 2], "radius": 0.5},
                                                      {"position": [2.8, 2], "radius": 0.5})")),
            "scene.json: saved from a running simulation: balls[2] overlaps balls[1] by 40% of "
            "the smaller radius");
}

TEST(SavedStates, NoWarningForWhatAHandWrittenSceneMayHold) {
  EXPECT_EQ(warningFor(savedSceneWithBalls(R"({"position": [0.48, 4], "radius": 0.5},
                                              {"position": [2, 2], "radius": 0.5},
                                              {"position": [2.98, 2], "radius": 0.5})")),
            "(no warning)");
  // Past a wall that is off, and overlapping while collisions are off: normal states.
  EXPECT_EQ(warningFor(sceneWith(std::string(kSavedFrom) +
                                 R"(, "walls": {"bottom": false}, "ball_collisions": false,
                                    "balls": [{"position": [8, -40], "radius": 0.5},
                                              {"position": [2, 2], "radius": 0.5},
                                              {"position": [2, 2], "radius": 0.5}])")),
            "(no warning)");
  // A hand-written scene never warns: it is refused instead.
  EXPECT_EQ(savedStateWarning(parseScene(sceneWith(), "x"), "x"), "");
}

TEST(SavedStates, HandWrittenScenesKeepTheOverlapAndInsideTheBoxRules) {
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [2, 2], "radius": 0.5},
                                        {"position": [2.94, 2], "radius": 0.5})")),
            "scene.json: balls[1]: overlaps balls[0] by 12% of the smaller radius (the limit is "
            "5%)");
  EXPECT_EQ(errorFrom(sceneWithBalls(R"({"position": [8, 0.4], "radius": 0.5})")),
            "scene.json: balls[0].position: the ball crosses the bottom wall by 0.1 m, more than "
            "5% of its radius");
}

TEST(SavedStates, EveryOtherRuleStillHolds) {
  EXPECT_EQ(errorFrom(savedSceneWithBalls(R"({"position": [2, 2], "radius": -1})")),
            "scene.json: balls[0].radius: must be > 0 (got -1)");
  EXPECT_EQ(errorFrom(savedSceneWithBalls(R"({"position": [2, 2], "radius": 1, "mass": 0})")),
            "scene.json: balls[0].mass: must be > 0 (got 0)");
  EXPECT_EQ(errorFrom(savedSceneWithBalls(R"({"position": [2, 2], "radius": 1, "spin": 0})")),
            "scene.json: balls[0]: unknown key \"spin\" (known keys: position, velocity, radius, "
            "mass, color)");
  EXPECT_EQ(errorFrom(savedSceneWithBalls(R"({"position": [2, "2"], "radius": 1})")),
            "scene.json: balls[0].position[1]: must be a number (got the string \"2\")");
  Scene scene = savedState();
  scene.balls[0].velocity.x = kNaN;
  EXPECT_EQ(validationError(scene), "state: balls[0].velocity[0]: must be finite (got nan)");
  scene = savedState();
  scene.balls.assign(kMaxBalls + 1, ballAt({2.0, 2.0}));
  EXPECT_EQ(validationError(scene),
            "state: balls: has 2000001 balls, more than the limit of 2000000");
}

TEST(SavedStates, MalformedSavedFromIsAnError) {
  const auto errorWith = [](std::string_view savedFrom) {
    return errorFrom(sceneWith(R"("saved_from": )" + std::string(savedFrom)));
  };
  EXPECT_EQ(errorWith(R"("elastic")"),
            "scene.json: saved_from: must be an object (got the string \"elastic\")");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "time": 1, "when": 2})"),
            "scene.json: saved_from: unknown key \"when\" (known keys: backend, options, time)");
  EXPECT_EQ(errorWith(R"({"time": 1})"),
            "scene.json: saved_from: missing required key \"backend\"");
  EXPECT_EQ(errorWith(R"({"backend": "elastic"})"),
            "scene.json: saved_from: missing required key \"time\"");
  EXPECT_EQ(errorWith(R"({"backend": 3, "time": 1})"),
            "scene.json: saved_from.backend: must be a string (got the number 3)");
  EXPECT_EQ(errorWith(R"({"backend": "", "time": 1})"),
            "scene.json: saved_from.backend: must be a backend name of 1 to 64 letters, digits, "
            "'_' or '-' (got \"\")");
  EXPECT_EQ(errorWith(R"({"backend": "elastic:substeps=4", "time": 1})"),
            "scene.json: saved_from.backend: must be a backend name of 1 to 64 letters, digits, "
            "'_' or '-' (got \"elastic:substeps=4\")");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "time": -0.5})"),
            "scene.json: saved_from.time: must be >= 0 (got -0.5)");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "time": "12.5"})"),
            "scene.json: saved_from.time: must be a number (got the string \"12.5\")");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "time": 1e999})"),
            "scene.json: saved_from.time: the number 1e999 is beyond the range of a double");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "options": [4], "time": 1})"),
            "scene.json: saved_from.options: must be an object (got an array of 1 element)");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "options": {"substeps": true}, "time": 1})"),
            "scene.json: saved_from.options.substeps: must be a number (got true)");
  EXPECT_EQ(errorWith(R"({"backend": "elastic", "options": {"sub steps\n": 4}, "time": 1})"),
            "scene.json: saved_from.options: must be an option name of 1 to 64 letters, digits, "
            "'_' or '-' (got \"sub steps\\x0a\")");
}

TEST(SavedStates, NonFiniteSavedFromValuesAreRefusedInMemory) {
  Scene scene = savedState();
  scene.savedFrom->time = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validationError(scene), "state: saved_from.time: must be finite (got inf)");
  scene = savedState();
  scene.savedFrom->options["substeps"] = kNaN;
  EXPECT_EQ(validationError(scene), "state: saved_from.options.substeps: must be finite (got nan)");
  EXPECT_THROW(writeScene(scene), SceneError);
}

// --- Files -------------------------------------------------------------------------------------

/// A fresh directory per test, removed afterwards.
class SceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("fooball_scene_file_test_" + std::to_string(::getpid()) + "_" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path file(std::string_view name) const { return directory_ / name; }

  static void writeText(const std::filesystem::path& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }

  static std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  static std::string loadError(const std::filesystem::path& path) {
    try {
      loadSceneFile(path);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "(no error)";
  }

  std::vector<std::string> directoryListing() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(directory_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  std::filesystem::path directory_;
};

TEST_F(SceneFiles, SavedSceneLoadsBackBitForBit) {
  const Scene scene = awkwardScene();
  saveSceneFile(scene, file("scene.json"));
  expectSameScene(scene, loadSceneFile(file("scene.json")));
}

TEST_F(SceneFiles, ErrorsNameTheFileAsGiven) {
  writeText(file("bad.json"), sceneWith(R"("gravity": [0])"));
  EXPECT_EQ(loadError(file("bad.json")),
            file("bad.json").string() + ": gravity: must be [x, y] (got an array of 1 element)");
}

TEST_F(SceneFiles, MissingFileCannotBeOpened) {
  EXPECT_EQ(loadError(file("missing.json")),
            file("missing.json").string() + ": cannot open: No such file or directory");
}

TEST_F(SceneFiles, DirectoryCannotBeOpened) {
  EXPECT_EQ(loadError(directory_), directory_.string() + ": cannot open: Is a directory");
}

TEST_F(SceneFiles, FileOverTheSizeLimitIsRefusedBeforeReading) {
  // Sparse files: no disk space or reading needed, so the refusal must come from the size.
  const auto path = file("huge.json");
  writeText(path, "");
  std::filesystem::resize_file(path, kMaxSceneFileBytes + 1);
  EXPECT_EQ(loadError(path), path.string() + ": file is 512.1 MiB, larger than the 512 MiB limit");
  std::filesystem::resize_file(path, 600ull << 20);
  EXPECT_EQ(loadError(path), path.string() + ": file is 600 MiB, larger than the 512 MiB limit");
}

TEST_F(SceneFiles, EmptyFileIsInvalidJson) {
  writeText(file("empty.json"), "");
  EXPECT_EQ(loadError(file("empty.json")),
            file("empty.json").string() + ": invalid JSON: the text is empty");
}

TEST_F(SceneFiles, TruncatedFileIsInvalidJson) {
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0}), ballAt({6.0, 2.0})};
  const std::string text = writeScene(scene);
  writeText(file("cut.json"), text.substr(0, text.size() / 2));
  EXPECT_EQ(
      loadError(file("cut.json")).rfind(file("cut.json").string() + ": invalid JSON at line ", 0),
      0u)
      << loadError(file("cut.json"));
}

TEST_F(SceneFiles, BinaryFileIsInvalidJson) {
  writeText(file("image.png"), std::string("\x89PNG\r\n\x1a\n\0\0\0\r", 12));
  EXPECT_EQ(loadError(file("image.png")),
            file("image.png").string() +
                ": invalid JSON at line 1, column 1: syntax error while parsing value - invalid "
                "literal; last read: '\\x89'");
}

TEST_F(SceneFiles, DeeplyNestedFileIsRefused) {
  writeText(file("deep.json"), std::string(1 << 20, '['));
  EXPECT_EQ(loadError(file("deep.json")),
            file("deep.json").string() +
                ": invalid JSON at line 1, column 65: nested more than 64 levels deep");
}

TEST_F(SceneFiles, SaveReplacesTheFileAndLeavesNoTemporary) {
  writeText(file("scene.json"), "old contents");
  Scene scene;
  scene.balls = {ballAt({2.0, 2.0})};
  saveSceneFile(scene, file("scene.json"));
  EXPECT_EQ(readText(file("scene.json")), writeScene(scene));
  EXPECT_EQ(directoryListing(), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, FailedSaveLeavesTheOldFileIntact) {
  writeText(file("scene.json"), "old contents");
  Scene scene;
  scene.balls = {ballAt({2.0, kNaN})};
  EXPECT_THROW(
      {
        try {
          saveSceneFile(scene, file("scene.json"));
        } catch (const SceneError& error) {
          EXPECT_EQ(error.what(), file("scene.json").string() +
                                      ": balls[0].position[1]: cannot be written: JSON has no nan");
          throw;
        }
      },
      SceneError);
  EXPECT_EQ(readText(file("scene.json")), "old contents");
  EXPECT_EQ(directoryListing(), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, SaveIntoAMissingDirectoryNamesThePath) {
  const auto path = file("no/such/dir/scene.json");
  EXPECT_THROW(
      {
        try {
          saveSceneFile(Scene{}, path);
        } catch (const SceneError& error) {
          EXPECT_EQ(error.what(), path.string() + ": cannot write: No such file or directory");
          throw;
        }
      },
      SceneError);
  EXPECT_TRUE(directoryListing().empty());
}

TEST_F(SceneFiles, SaveOverADirectoryFailsAndCleansUp) {
  std::filesystem::create_directory(file("taken"));
  EXPECT_THROW(saveSceneFile(Scene{}, file("taken")), SceneError);
  EXPECT_EQ(directoryListing(), std::vector<std::string>{"taken"});
}

}  // namespace
}  // namespace fooball
