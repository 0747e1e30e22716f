// Writing scene files: version 1, every key explicit, every ball explicit (random_balls is
// never written). Doubles use the shortest text that reads back to the same bits, with ".0"
// on whole numbers so they stay JSON floats (and "-0.0" keeps its sign). One ball per line
// keeps a million-ball file compact and still easy to diff. "saved_from", when the scene has
// it, comes before the balls, so it is seen at the top of the file.

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include "fooball/scene_file.h"
#include "json_place.h"
#include "message_text.h"

namespace fooball {
namespace {

void appendNumber(std::string& out, double value, const Place& place) {
  if (!std::isfinite(value)) {
    failAt(place, "cannot be written: JSON has no " + exactNumberText(value));
  }
  const std::string text = exactNumberText(value);
  out += text;
  if (text.find_first_of(".e") == std::string::npos) out += ".0";
}

void appendVec2(std::string& out, Vec2 value, const Place& place) {
  out += '[';
  appendNumber(out, value.x, place.index(0));
  out += ", ";
  appendNumber(out, value.y, place.index(1));
  out += ']';
}

void appendBool(std::string& out, bool value) {
  out += value ? "true" : "false";
}

void appendString(std::string& out, const std::string& value, const Place& place) {
  try {
    out += nlohmann::json(value).dump();
  } catch (const nlohmann::json::type_error&) {
    failAt(place, "cannot be written: not valid UTF-8");
  }
}

void appendColor(std::string& out, std::uint32_t color, const Place& place) {
  if (color > 0xffffffu) failAt(place, "cannot be written: not a 0xRRGGBB colour");
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "\"#%06x\"", color);
  out += text.data();
}

void appendBall(std::string& out, const BallDef& ball, const Place& place) {
  out += "{\"position\": ";
  appendVec2(out, ball.position, place.key("position"));
  out += ", \"velocity\": ";
  appendVec2(out, ball.velocity, place.key("velocity"));
  out += ", \"radius\": ";
  appendNumber(out, ball.radius, place.key("radius"));
  out += ", \"mass\": ";
  appendNumber(out, ball.mass, place.key("mass"));
  out += ", \"color\": ";
  appendColor(out, ball.color, place.key("color"));
  out += '}';
}

/// An option's value as JSON writes it: whole numbers as integers ("substeps": 4, as a user
/// would write a count), anything else as the shortest round-trip text; -0.0 keeps its sign.
void appendOptionValue(std::string& out, double value, const Place& place) {
  if (!std::isfinite(value)) {
    failAt(place, "cannot be written: JSON has no " + exactNumberText(value));
  }
  out += value == 0.0 && std::signbit(value) ? "-0.0" : exactNumberText(value);
}

/// {"backend": "elastic", "options": {"substeps": 4, "threads": 1}, "time": 12.5}, the options
/// in name order (a std::map): write → read → write gives the same bytes.
void appendSavedFrom(std::string& out, const SavedFrom& from, const Place& place) {
  out += "{\"backend\": ";
  appendString(out, from.backend, place.key("backend"));
  out += ", \"options\": {";
  const Place options = place.key("options");
  bool first = true;
  for (const auto& [name, value] : from.options) {
    out += first ? "" : ", ";
    first = false;
    appendString(out, name, options);
    out += ": ";
    appendOptionValue(out, value, options.key(name));
  }
  out += "}, \"time\": ";
  appendNumber(out, from.time, place.key("time"));
  out += '}';
}

[[noreturn]] void failToWrite(const std::filesystem::path& path, std::string_view reason) {
  throw SceneError(withSource(path.string(), "cannot write: " + std::string(reason)));
}

}  // namespace

std::string writeScene(const Scene& scene) {
  constexpr std::size_t kBytesPerBall = 200;  // full-precision numbers and the keys
  std::string out;
  out.reserve(512 + kBytesPerBall * scene.balls.size());
  const Place top;
  const WorldSettings& world = scene.world;
  out += "{\n  \"format\": \"fooball-scene\",\n  \"version\": 1,\n  \"name\": ";
  appendString(out, scene.name, top.key("name"));
  const Place box = top.key("box");
  out += ",\n  \"box\": {\"width\": ";
  appendNumber(out, scene.box.width, box.key("width"));
  out += ", \"height\": ";
  appendNumber(out, scene.box.height, box.key("height"));
  out += "},\n  \"walls\": {\"left\": ";
  appendBool(out, world.walls.left);
  out += ", \"right\": ";
  appendBool(out, world.walls.right);
  out += ", \"bottom\": ";
  appendBool(out, world.walls.bottom);
  out += ", \"top\": ";
  appendBool(out, world.walls.top);
  out += "},\n  \"gravity\": ";
  appendVec2(out, world.gravity, top.key("gravity"));
  out += ",\n  \"air_resistance\": ";
  appendNumber(out, world.airResistance, top.key("air_resistance"));
  out += ",\n  \"ball_collisions\": ";
  appendBool(out, world.ballCollisions);
  if (scene.dt) {
    out += ",\n  \"dt\": ";
    appendNumber(out, *scene.dt, top.key("dt"));
  }
  if (scene.savedFrom) {
    out += ",\n  \"saved_from\": ";
    appendSavedFrom(out, *scene.savedFrom, top.key("saved_from"));
  }
  out += ",\n  \"balls\": [";
  const Place balls = top.key("balls");
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    out += i == 0 ? "\n    " : ",\n    ";
    appendBall(out, scene.balls[i], balls.index(i));
  }
  out += scene.balls.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

void saveSceneFile(const Scene& scene, const std::filesystem::path& path) {
  std::string text;
  try {
    text = writeScene(scene);
  } catch (const SceneError& error) {
    throw SceneError(withSource(path.string(), error.what()));
  }
  // Beside the target, so the rename stays within one file system and replaces it atomically.
  std::filesystem::path temporary = path;
  temporary += ".saving";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) failToWrite(path, std::error_code(errno, std::generic_category()).message());
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      const std::string reason = std::error_code(errno, std::generic_category()).message();
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      failToWrite(path, reason);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    failToWrite(path, error.message());
  }
}

}  // namespace fooball
