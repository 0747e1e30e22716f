#include "fooball/presets.h"

#include <algorithm>
#include <string>

#include "fooball/scene_file.h"
#include "message_text.h"
#include "preset_data.h"

namespace fooball {
namespace {

constexpr Preset kPresets[] = {
    {"default", "a few dozen balls of mixed sizes bouncing under gravity", preset_data::k_default},
    {"gas", "an ideal gas: 300 equal balls at random speeds, no gravity", preset_data::k_gas},
    {"head-on", "two equal balls meet head-on and swap velocities", preset_data::k_head_on},
    {"glancing", "an off-centre hit on a ball at rest: they leave at right angles",
     preset_data::k_glancing},
    {"cradle", "Newton's cradle: one ball into a row of five touching ones", preset_data::k_cradle},
    {"billiards", "a fast cue ball breaks a rack of 15 touching balls", preset_data::k_billiards},
    {"mass-ratio", "a 100:1 pair against a wall: 31 collisions, the first digits of pi",
     preset_data::k_mass_ratio},
    {"tunnelling", "a fast small ball at a gap narrower than itself: bounce or tunnel through?",
     preset_data::k_tunnelling},
    {"dense", "759 equal balls at 66% packing: a crowd where collisions never stop",
     preset_data::k_dense},
    {"rain", "small balls fall under gravity from high up and settle into a pile",
     preset_data::k_rain},
};

}  // namespace

std::span<const Preset> presets() {
  return kPresets;
}

Scene loadPreset(std::string_view name) {
  const std::string source = "preset '" + printableText(name) + "'";
  const auto preset = std::find_if(std::begin(kPresets), std::end(kPresets),
                                   [name](const Preset& p) { return p.name == name; });
  if (preset == std::end(kPresets)) {
    std::string names;
    for (const Preset& p : kPresets) {
      if (!names.empty()) names += ", ";
      names += p.name;
    }
    throw SceneError(source + ": no such preset (the presets are: " + names + ")");
  }
  return parseScene(preset->json, source);
}

}  // namespace fooball
