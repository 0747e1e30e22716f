// libFuzzer target for parseScene (engine/include/fooball/scene_file.h). Every input must either
// parse to a scene that passes validateScene and survives writeScene → parseScene bit for bit
// (saved_from included) and writeScene → parseScene → writeScene byte for byte,
// or be refused with a SceneError whose message is one non-empty line. Anything else — a crash,
// a sanitizer report, another exception, a multi-line or empty message — aborts.

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fooball/scene_file.h"

namespace {

using namespace fooball;

[[noreturn]] void fail(std::string_view problem, std::string_view detail) {
  std::fprintf(stderr, "scene_reader_fuzzer: %.*s: %.*s\n", static_cast<int>(problem.size()),
               problem.data(), static_cast<int>(detail.size()), detail.data());
  std::abort();
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool sameBits(Vec2 a, Vec2 b) {
  return sameBits(a.x, b.x) && sameBits(a.y, b.y);
}

/// Bit for bit, so -0.0 against 0.0 or a last-digit change in the writer counts as different.
bool sameScene(const Scene& a, const Scene& b) {
  if (a.name != b.name || !sameBits(a.box.width, b.box.width) ||
      !sameBits(a.box.height, b.box.height) || !sameBits(a.world.gravity, b.world.gravity) ||
      !sameBits(a.world.airResistance, b.world.airResistance) ||
      a.world.ballCollisions != b.world.ballCollisions || a.world.walls != b.world.walls ||
      a.balls.size() != b.balls.size() || a.savedFrom.has_value() != b.savedFrom.has_value()) {
    return false;
  }
  if (a.savedFrom) {
    const SavedFrom& x = *a.savedFrom;
    const SavedFrom& y = *b.savedFrom;
    if (x.backend != y.backend || !sameBits(x.time, y.time) || x.options.size() != y.options.size())
      return false;
    for (const auto& [name, value] : x.options) {
      const auto other = y.options.find(name);
      if (other == y.options.end() || !sameBits(value, other->second)) return false;
    }
  }
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const BallDef& x = a.balls[i];
    const BallDef& y = b.balls[i];
    if (!sameBits(x.position, y.position) || !sameBits(x.velocity, y.velocity) ||
        !sameBits(x.radius, y.radius) || !sameBits(x.mass, y.mass) || x.color != y.color) {
      return false;
    }
  }
  return true;
}

void checkRefusal(const SceneError& error) {
  const std::string_view message = error.what();
  if (message.empty()) fail("empty SceneError message", "");
  if (message.find_first_of("\r\n") != std::string_view::npos)
    fail("SceneError message is not one line", message);
}

void checkAccepted(const Scene& scene) {
  try {
    validateScene(scene, "fuzz");
  } catch (const SceneError& error) {
    fail("parseScene accepted a scene validateScene refuses", error.what());
  }
  std::string written;
  try {
    written = writeScene(scene);
    const Scene reread = parseScene(written, "round trip");
    if (!sameScene(reread, scene))
      fail("writeScene → parseScene changed the scene", written.substr(0, 2000));
    if (writeScene(reread) != written)
      fail("writeScene → parseScene → writeScene changed the bytes", written.substr(0, 2000));
    // The warning of a saved state is one line too.
    const std::string warning = savedStateWarning(reread, "fuzz");
    if (warning.find_first_of("\r\n") != std::string::npos)
      fail("savedStateWarning is not one line", warning);
  } catch (const SceneError& error) {
    fail("parseScene refuses what writeScene wrote", error.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    checkAccepted(parseScene(text, "fuzz"));
  } catch (const SceneError& error) {
    checkRefusal(error);
  } catch (const std::exception& error) {
    fail("unexpected exception", error.what());
  }
  return 0;
}
