#include "fooball/presets.h"

#include <algorithm>
#include <string>

#include "fooball/scene_file.h"
#include "message_text.h"
#include "preset_data.h"

namespace fooball {
namespace {

constexpr Preset kPresets[] = {
    {"default", "a few dozen balls of mixed sizes bouncing under gravity",
     "Big and small balls bounce and collide under gravity. In the Energy chart kinetic and "
     "potential energy trade places at every bounce while their sum stays flat: the residual, "
     "the method's own error, stays at rounding level.",
     preset_data::k_default},
    {"gas", "an ideal gas: 300 equal balls at random speeds, no gravity",
     "300 equal balls start at speeds from 0.5 to 4 m/s. Collisions share the energy out until "
     "the speeds follow the 2-D Maxwell–Boltzmann distribution: with temperature colouring on, "
     "some balls crawl and some race faster than any started; the total energy never changes.",
     preset_data::k_gas},
    {"head-on", "two equal balls meet head-on and swap velocities",
     "Turn on velocity vectors (View menu) and watch the hit: the arrows trade places, each ball "
     "leaving with the other's velocity, as conserving momentum and energy demands for equal "
     "masses.",
     preset_data::k_head_on},
    {"glancing", "an off-centre hit on a ball at rest: they leave at right angles",
     "Turn on velocity vectors (View menu): after the off-centre hit the two arrows stand at a "
     "right angle. For equal masses, conserving momentum and energy leaves no other way.",
     preset_data::k_glancing},
    {"cradle", "Newton's cradle: one ball into a row of five touching ones",
     "The striker's momentum passes ball to ball along the row: only the last ball leaves, at "
     "the striker's speed, and the others stay still. Box2D and XPBD solve the touching row at "
     "once and share the momentum out instead (compare them).",
     preset_data::k_cradle},
    {"billiards", "a fast cue ball breaks a rack of 15 touching balls",
     "The cue ball at 12 m/s breaks a rack of 15 touching balls. A few balls barely move at "
     "first, but within 20 s every one of the sixteen has been hit and set moving, and the total "
     "energy stays exactly what the cue ball brought.",
     preset_data::k_billiards},
    {"mass-ratio", "a 100:1 pair against a wall: 31 collisions, the first digits of pi",
     "The heavy ball (100 times the mass) drives the light one against the wall, where it "
     "rattles until the heavy ball turns back. Count the hits: 16 ball–ball and 15 wall "
     "bounces, 31 in all, the first digits of π (a ratio of 10,000 gives 314); the last comes "
     "at about 30 s, when the light ball catches the heavy one up.",
     preset_data::k_mass_ratio, true},
    {"tunnelling", "a fast small ball at a gap narrower than itself: bounce or tunnel through?",
     "The ball is wider than the gap, so it should bounce back. At the default 4 substeps it "
     "moves 0.625 m per substep, past the whole stretch where it would touch the gap's balls, "
     "so no substep finds a contact and it passes straight through; at 16 substeps, or with "
     "exact, it bounces.",
     preset_data::k_tunnelling},
    {"dense", "759 equal balls at 66% packing: a crowd where collisions never stop",
     "759 balls fill two thirds of the box, so each is always about to hit another: the "
     "Counters climb by over ten thousand collisions a second. Their overlap column shows how "
     "far a time-stepped method lets balls sink into each other.",
     preset_data::k_dense},
    {"rain", "small balls fall under gravity from high up and settle into a pile",
     "Balls rain down and, slowed by air resistance (0.5 1/s), settle into a pile within about "
     "20 s. The pile never quite freezes: the method adds a little energy at resting contacts, "
     "which drag takes out again; the energy residual chart shows that creep.",
     preset_data::k_rain},
};

}  // namespace

std::span<const Preset> presets() {
  return kPresets;
}

const Preset* findPreset(std::string_view name) {
  const auto preset = std::find_if(std::begin(kPresets), std::end(kPresets),
                                   [name](const Preset& p) { return p.name == name; });
  return preset == std::end(kPresets) ? nullptr : preset;
}

Scene loadPreset(std::string_view name) {
  const std::string source = "preset '" + printableText(name) + "'";
  const Preset* preset = findPreset(name);
  if (preset == nullptr) {
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
