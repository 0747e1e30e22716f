// Reading scene files (DESIGN.md, "Scene files"). Where DESIGN.md is silent:
// - "name" defaults to "": the name is what the file says (an app may show the file name);
// - a ball needs "position" and "radius"; "velocity" defaults to [0, 0], "mass" to
//   1 kg/m² × π r², "color" to defaultBallColor(index);
// - "random_balls" needs "count", "radius" and "speed"; "density" defaults to 1 kg/m², "seed"
//   to 1; its balls follow the explicit ones, so their indices and colours continue theirs;
// - counts and seeds are JSON integers: 2.0 is refused, like any other non-integer;
// - a key repeated in one object is an error (plain JSON would keep the last silently);
// - "saved_from" needs "backend" and "time"; "options" defaults to none. Its names are words of
//   letters, digits, '_' and '-', as run specs write them (NAME:KEY=VALUE); see scene.h, SavedFrom;
// - "format" and "version" are checked first, so a file of another kind or a newer version
//   says so before anything else; then JSON types, then values (scene_validation.cpp).

#include <optional>
#include <string>
#include <vector>

#include "bounded_file.h"
#include "fooball/random_balls.h"
#include "fooball/scene_file.h"
#include "json_reading.h"
#include "message_text.h"
#include "scene_checks.h"
#include "scene_json.h"

namespace fooball {
namespace {

using Json = nlohmann::json;

constexpr std::string_view kFormat = "fooball-scene";
constexpr std::uint64_t kVersion = 1;

BallDef readBall(const Json& object, const Place& place, std::size_t index) {
  requireObject(object, place);
  checkKnownKeys(object, place, {"position", "velocity", "radius", "mass", "color"});
  BallDef ball;
  ball.position = readVec2(requireMember(object, place, "position"), place.key("position"));
  if (const Json* velocity = findMember(object, "velocity")) {
    ball.velocity = readVec2(*velocity, place.key("velocity"));
  }
  ball.radius = readNumber(requireMember(object, place, "radius"), place.key("radius"));
  const Json* mass = findMember(object, "mass");
  ball.mass = mass != nullptr ? readNumber(*mass, place.key("mass")) : diskMass(ball.radius);
  const Json* color = findMember(object, "color");
  ball.color = color != nullptr ? readColor(*color, place.key("color")) : defaultBallColor(index);
  return ball;
}

/// Takes the balls as the parser streams them. A bad ball is remembered, not thrown, so that
/// the top-level checks (format, version) come first whatever the order of keys in the file;
/// too many balls outranks a bad one, and stops the collecting.
class BallCollector {
 public:
  void take(const Json& element, std::size_t index) {
    if (index >= kMaxBalls) tooMany_ = true;
    if (tooMany_ || !firstError_.empty()) return;
    const Place top;
    const Place balls = top.key("balls");
    try {
      balls_.push_back(readBall(element, balls.index(index), index));
    } catch (const SceneError& error) {
      firstError_ = error.what();
    }
  }

  std::vector<BallDef> release() {
    if (tooMany_) {
      const Place top;
      failAt(top.key("balls"), "has more than " + std::to_string(kMaxBalls) + " balls (the limit)");
    }
    if (!firstError_.empty()) throw SceneError(firstError_);
    return std::move(balls_);
  }

 private:
  std::vector<BallDef> balls_;
  std::string firstError_;
  bool tooMany_ = false;
};

void checkFormatAndVersion(const Json& root, const Place& top) {
  if (!root.is_object())
    failAt(top, "a scene must be a JSON object (got " + describeJson(root) + ")");
  const Json& format = requireMember(root, top, "format");
  if (!format.is_string() || format.get_ref<const std::string&>() != kFormat) {
    failAt(top.key("format"),
           "must be \"" + std::string(kFormat) + "\" (got " + describeJson(format) + ")");
  }
  const Place versionPlace = top.key("version");
  const Json& version = requireMember(root, top, "version");
  if (!version.is_number_integer()) {
    failAt(versionPlace, "must be the integer " + std::to_string(kVersion) + " (got " +
                             describeJson(version) + ")");
  }
  if (!version.is_number_unsigned() || version.get<std::uint64_t>() != kVersion) {
    failAt(versionPlace, "unsupported version " + version.dump() + " (this build reads version " +
                             std::to_string(kVersion) + ")");
  }
}

Box readBox(const Json& object, const Place& place) {
  requireObject(object, place);
  checkKnownKeys(object, place, {"width", "height"});
  return {readNumber(requireMember(object, place, "width"), place.key("width")),
          readNumber(requireMember(object, place, "height"), place.key("height"))};
}

Walls readWalls(const Json& object, const Place& place) {
  requireObject(object, place);
  checkKnownKeys(object, place, {"left", "right", "bottom", "top"});
  Walls walls;
  for (auto [name, wall] : {std::pair{"left", &walls.left}, std::pair{"right", &walls.right},
                            std::pair{"bottom", &walls.bottom}, std::pair{"top", &walls.top}}) {
    if (const Json* value = findMember(object, name)) *wall = readBool(*value, place.key(name));
  }
  return walls;
}

RandomBalls readRandomBalls(const Json& object, const Place& place) {
  requireObject(object, place);
  checkKnownKeys(object, place, {"count", "radius", "speed", "density", "seed"});
  RandomBalls spec;
  spec.count = readUnsigned(requireMember(object, place, "count"), place.key("count"));
  const auto radius =
      readNumberPair(requireMember(object, place, "radius"), place.key("radius"), "[min, max]");
  spec.minRadius = radius[0];
  spec.maxRadius = radius[1];
  const auto speed =
      readNumberPair(requireMember(object, place, "speed"), place.key("speed"), "[min, max]");
  spec.minSpeed = speed[0];
  spec.maxSpeed = speed[1];
  if (const Json* density = findMember(object, "density")) {
    spec.density = readNumber(*density, place.key("density"));
  }
  if (const Json* seed = findMember(object, "seed"))
    spec.seed = readUnsigned(*seed, place.key("seed"));
  return spec;
}

SavedFrom readSavedFrom(const Json& object, const Place& place) {
  requireObject(object, place);
  checkKnownKeys(object, place, {"backend", "options", "time"});
  SavedFrom from;
  from.backend = readString(requireMember(object, place, "backend"), place.key("backend"));
  if (const Json* options = findMember(object, "options")) {
    const Place optionsPlace = place.key("options");
    requireObject(*options, optionsPlace);
    for (const auto& [name, value] : options->items()) {
      // The name first: the place of a bad value quotes it, and must stay one printable line.
      checkSpecName(name, optionsPlace, "an option name");
      from.options[name] = readNumber(value, optionsPlace.key(name));
    }
  }
  from.time = readNumber(requireMember(object, place, "time"), place.key("time"));
  return from;
}

Scene readScene(std::string_view text) {
  BallCollector collector;
  const Json root = parseSceneJson(
      text, "balls",
      [&collector](const Json& element, std::size_t index) { collector.take(element, index); });
  const Place top;
  checkFormatAndVersion(root, top);
  checkKnownKeys(root, top,
                 {"format", "version", "name", "box", "walls", "gravity", "air_resistance",
                  "ball_collisions", "dt", "balls", "random_balls", "saved_from"});
  Scene scene;
  if (const Json* name = findMember(root, "name")) scene.name = readString(*name, top.key("name"));
  scene.box = readBox(requireMember(root, top, "box"), top.key("box"));
  if (const Json* walls = findMember(root, "walls"))
    scene.world.walls = readWalls(*walls, top.key("walls"));
  if (const Json* gravity = findMember(root, "gravity")) {
    scene.world.gravity = readVec2(*gravity, top.key("gravity"));
  }
  if (const Json* airResistance = findMember(root, "air_resistance")) {
    scene.world.airResistance = readNumber(*airResistance, top.key("air_resistance"));
  }
  if (const Json* ballCollisions = findMember(root, "ball_collisions")) {
    scene.world.ballCollisions = readBool(*ballCollisions, top.key("ball_collisions"));
  }
  if (const Json* dt = findMember(root, "dt")) scene.dt = readNumber(*dt, top.key("dt"));
  if (const Json* savedFrom = findMember(root, "saved_from")) {
    scene.savedFrom = readSavedFrom(*savedFrom, top.key("saved_from"));
  }
  if (const Json* balls = findMember(root, "balls"); balls != nullptr && !balls->is_array()) {
    failAt(top.key("balls"), "must be an array (got " + describeJson(*balls) + ")");
  }
  scene.balls = collector.release();
  std::optional<RandomBalls> randomBalls;
  if (const Json* spec = findMember(root, "random_balls")) {
    randomBalls = readRandomBalls(*spec, top.key("random_balls"));
  }
  checkScene(scene);
  if (randomBalls) addRandomBalls(scene, *randomBalls);
  return scene;
}

}  // namespace

Scene parseScene(std::string_view text, std::string_view source) {
  try {
    return readScene(text);
  } catch (const SceneError& error) {
    throw SceneError(withSource(source, error.what()));
  }
}

Scene loadSceneFile(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::string text;
  try {
    text = readBoundedFile(path, kMaxSceneFileBytes);
  } catch (const SceneError& error) {
    throw SceneError(withSource(source, error.what()));
  }
  return parseScene(text, source);
}

}  // namespace fooball
