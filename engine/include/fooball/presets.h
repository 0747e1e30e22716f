#pragma once

#include <span>
#include <string_view>

#include "fooball/scene.h"

namespace fooball {

/// A built-in scene: a scene file compiled into the program (engine/presets/NAME.json).
struct Preset {
  std::string_view name;
  std::string_view description;  ///< one line: what the scene teaches
  std::string_view json;
};

std::span<const Preset> presets();

/// The preset's scene; throws SceneError naming the known presets when `name` is unknown.
Scene loadPreset(std::string_view name);

/// The scene the programs start on when given none.
inline constexpr std::string_view kDefaultPreset = "default";

}  // namespace fooball
