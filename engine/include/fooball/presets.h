#pragma once

#include <span>
#include <string_view>

#include "fooball/scene.h"

namespace fooball {

/// A built-in scene: a scene file compiled into the program (engine/presets/NAME.json), with
/// what it teaches. Every caption is true at the app's defaults (the first registered backend
/// with its default options, dt = 1/60 s): tests/preset_promises_test.cpp holds each one to it.
struct Preset {
  std::string_view name;
  std::string_view description;  ///< one line: what the scene teaches
  /// "What to look for": 1–3 sentences on what to watch and what it proves.
  std::string_view lookFor;
  std::string_view json;
  /// The promise is a count of collisions: the app shows each run's ball–ball and wall
  /// collisions beside the caption.
  bool countsCollisions = false;
};

std::span<const Preset> presets();

/// The preset called `name`, or nullptr.
const Preset* findPreset(std::string_view name);

/// The preset's scene; throws SceneError naming the known presets when `name` is unknown.
Scene loadPreset(std::string_view name);

/// The scene the programs start on when given none.
inline constexpr std::string_view kDefaultPreset = "default";

}  // namespace fooball
