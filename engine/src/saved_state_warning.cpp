// The one-line warning for a saved state that breaks a rule of hand-written scenes (DESIGN.md,
// "Scene files"): a file with saved_from loads whatever a running simulation produced, and the
// user is told the worst of it. The rules are those checkScene waives for such a file — balls
// overlapping (while ball collisions are on) or crossing a wall that is on, by more than
// kContactSlop of the (smaller) radius — so a state a hand-written file could hold gets none.
// Worst means deepest as a fraction of the radius, since that is what the rules measure.

#include <optional>
#include <string>
#include <string_view>
#include <tuple>

#include "fooball/scene_file.h"
#include "message_text.h"
#include "overlap_search.h"

namespace fooball {
namespace {

/// The deepest reach of one ball past a wall that is on.
struct WallCrossing {
  std::size_t ball = 0;
  std::string_view wall;
  double depth = 0.0;     ///< m past the wall
  double fraction = 0.0;  ///< depth / radius
};

std::optional<WallCrossing> deepestWallCrossing(const Scene& scene) {
  const Walls& walls = scene.world.walls;
  std::optional<WallCrossing> deepest;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const double r = scene.balls[i].radius;
    const Vec2 p = scene.balls[i].position;
    for (const auto& [on, wall, depth] :
         {std::tuple{walls.left, "left", r - p.x},
          std::tuple{walls.right, "right", p.x + r - scene.box.width},
          std::tuple{walls.bottom, "bottom", r - p.y},
          std::tuple{walls.top, "top", p.y + r - scene.box.height}}) {
      if (!on || depth <= 0.0) continue;
      if (!deepest || depth / r > deepest->fraction)
        deepest = WallCrossing{i, wall, depth, depth / r};
    }
  }
  return deepest;
}

std::string percentText(double fraction) {
  return roundedNumberText(100.0 * fraction) + "%";
}

}  // namespace

std::string savedStateWarning(const Scene& scene, std::string_view source) {
  if (!scene.savedFrom) return {};
  std::string worst;
  double worstFraction = kContactSlop;  // anything up to it is fine in any scene
  if (const auto crossing = deepestWallCrossing(scene);
      crossing && crossing->fraction > worstFraction) {
    worstFraction = crossing->fraction;
    worst = "balls[" + std::to_string(crossing->ball) + "] crosses the " +
            std::string(crossing->wall) + " wall by " + roundedNumberText(crossing->depth) +
            " m, " + percentText(crossing->fraction) + " of its radius";
  }
  if (scene.world.ballCollisions) {
    if (const auto pair = deepestOverlap(scene.balls);
        pair && pair->depthFraction > worstFraction) {
      worst = "balls[" + std::to_string(pair->second) + "] overlaps balls[" +
              std::to_string(pair->first) + "] by " + percentText(pair->depthFraction) +
              " of the smaller radius";
    }
  }
  if (worst.empty()) return {};
  return withSource(source, "saved from a running simulation: " + worst);
}

}  // namespace fooball
