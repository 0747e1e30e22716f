#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fooball/interactions.h"
#include "fooball/options.h"
#include "fooball/scene.h"

namespace fooball::robustness {

/// A mouse tool held from step `start` for `duration` steps.
struct ToolUse {
  int start = 0;
  int duration = 1;
  MouseMode mode = MouseMode::Attract;
  Scope scope = Scope::All;
  Vec2 point;             ///< m, where it is pressed and held
  double strength = 1.0;  ///< Interactions::strength, 1/s²
};

/// New world settings from step `step` on.
struct WorldChange {
  int step = 0;
  WorldSettings world;
};

/// setBall at step `step`: the ball keeps its place, takes a new velocity, shrinks by
/// `radiusScale` (≤ 1, so it overlaps nothing new) and takes a new mass.
struct BallEdit {
  int step = 0;
  std::size_t index = 0;
  Vec2 velocity;             ///< m/s
  double radiusScale = 1.0;  ///< in (0, 1]
  double mass = 1.0;         ///< kg
};

/// One randomised run of a backend, everything drawn from `seed`: the same seed gives the same
/// case, so a failure is reproduced by its seed alone (FOOBALL_CASE_SEED).
struct RandomCase {
  std::uint64_t seed = 0;
  Scene scene;
  std::vector<std::pair<std::string, double>> options;  ///< backend option values to set
  double dt = 1.0 / 60.0;                               ///< s
  int steps = 0;
  std::vector<ToolUse> tools;
  std::vector<WorldChange> worldChanges;
  std::vector<BallEdit> edits;

  /// No tools, edits, drag or world changes: the total energy is the method's to keep.
  bool isolated() const;
  /// Every wall on for the whole run: no ball may leave the box.
  bool closed() const;
};

/// Draws a case for a backend with the given options: 0–200 balls in boxes of 0.5–200 m, two
/// size classes up to 100× apart, masses over six decades, speeds up to 5 box sides per second,
/// gravity up to 1000 m/s², drag, walls, tools, edits and live world changes, 1–400 steps.
/// Counts (balls, steps, substeps, iterations, threads) are log-uniform, so most cases are small
/// and cheap and a few are large (random_case.cpp gives each range and the reason for its
/// limits).
RandomCase drawCase(std::uint64_t seed, std::span<const OptionSpec> options);

/// Everything but the balls on one line each (the balls: writeScene(c.scene)).
std::string describe(const RandomCase& c);

}  // namespace fooball::robustness
