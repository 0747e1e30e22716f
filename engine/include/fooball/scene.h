#pragma once

#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "fooball/vec2.h"

namespace fooball {

/// Mass of a uniform disk: density (kg/m²) × π r².
inline double diskMass(double radius, double density = 1.0) {
  return density * std::numbers::pi * radius * radius;
}

/// One ball. Valid values are checked once, at the scene boundary (scene_file.h, validateScene);
/// everything inside the engine and the backends trusts them.
struct BallDef {
  Vec2 position;                   ///< m, centre, inside the box
  Vec2 velocity;                   ///< m/s
  double radius = 0.5;             ///< m, > 0
  double mass = diskMass(0.5);     ///< kg, > 0
  std::uint32_t color = 0xe0a030;  ///< 0xRRGGBB, drawing only
};

struct Walls {
  bool left = true;
  bool right = true;
  bool bottom = true;
  bool top = true;

  bool allOn() const { return left && right && bottom && top; }
  friend bool operator==(const Walls&, const Walls&) = default;
};

/// The settings that can change while a scene runs.
struct WorldSettings {
  Vec2 gravity;                ///< m/s², e.g. {0, -9.81}
  double airResistance = 0.0;  ///< 1/s, linear drag: dv/dt = -c·v
  bool ballCollisions = true;  ///< ball–ball collisions on/off
  Walls walls;
  friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

/// The box [0,width] × [0,height], origin bottom-left, y up.
struct Box {
  double width = 16.0;  ///< m
  double height = 9.0;  ///< m
  friend bool operator==(const Box&, const Box&) = default;
};

/// Where a state saved from a running simulation came from: a file's "saved_from" (DESIGN.md,
/// "Scene files"). A scene that has one may hold whatever a running simulation can produce —
/// balls overlapping each other or pressed into a wall beyond the contact slop — and loads with
/// a warning (savedStateWarning) instead of the hand-written scene's errors.
struct SavedFrom {
  /// The backend's registry name, e.g. "elastic". The engine knows no backend by name
  /// (DESIGN.md), so it checks only that this is a non-empty string: it is a record of where the
  /// state came from, and a file saved by a build with a backend this build lacks still opens.
  std::string backend;
  /// Every option of that backend with the value it had, by name (not only those off their
  /// defaults: the record stays true when a later build changes a default). A map, because a
  /// JSON object has no order: sorted by name, write → read → write gives the same bytes.
  std::map<std::string, double> options;
  double time = 0.0;  ///< s of simulated time the saving run had run since its scene was loaded
  friend bool operator==(const SavedFrom&, const SavedFrom&) = default;
};

/// s: the time step a scene runs at unless it names its own (Scene::dt) or a run is told
/// another (fooball-cli --dt, the app's time step field).
inline constexpr double kDefaultDt = 1.0 / 60.0;

struct Scene {
  std::string name;
  Box box;
  WorldSettings world;
  std::vector<BallDef> balls;
  /// Set in files FooBall wrote from a running simulation; absent in hand-written ones.
  std::optional<SavedFrom> savedFrom;
  /// s, > 0: the time step to run the scene at ("dt"); kDefaultDt when absent. Written only when
  /// it differs from kDefaultDt, so a scene at the default step reads as it always did.
  std::optional<double> dt;
};

/// Limits stated by the scene format; inputs beyond them are errors, not clamps.
inline constexpr std::size_t kMaxBalls = 2'000'000;
inline constexpr std::uintmax_t kMaxSceneFileBytes = 512ull << 20;  ///< 512 MiB
inline constexpr double kMaxBoxSide = 1e6;                          ///< m

/// How deep (as a fraction of the smaller radius) balls may already overlap each other or a wall
/// in a valid scene. Time-stepped solvers leave contacts this deep (Box2D's linear slop is
/// 5 mm), and a state they save must load back; anything deeper is an error.
inline constexpr double kContactSlop = 0.05;

/// The colour the format gives ball `index` when a file names none.
std::uint32_t defaultBallColor(std::size_t index);

}  // namespace fooball
