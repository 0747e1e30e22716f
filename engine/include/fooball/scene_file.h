#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "fooball/scene.h"
#include "fooball/scene_error.h"

namespace fooball {

/// Reads scene JSON (format "fooball-scene", version 1; see DESIGN.md). `source` names the text
/// in error messages: a file name, or "preset 'gas'". `random_balls` is expanded into explicit
/// balls here. Throws SceneError with one line naming the place and the reason. A file with
/// "saved_from" may hold overlapping balls and balls past a wall (see validateScene); ask
/// savedStateWarning what to tell the user about it.
Scene parseScene(std::string_view text, std::string_view source);

/// Reads and parses a file; refuses files larger than kMaxSceneFileBytes before reading them.
Scene loadSceneFile(const std::filesystem::path& path);

/// Writes version-1 JSON with every ball explicit; parseScene(writeScene(s)) == s, bit for bit
/// (doubles are written with round-trip precision).
std::string writeScene(const Scene& scene);

/// Writes to a temporary file beside `path` and renames it over `path`, so a failed write never
/// leaves a half-written scene behind.
void saveSceneFile(const Scene& scene, const std::filesystem::path& path);

/// Checks every rule of the format on an in-memory scene: finite numbers, positive sizes and
/// masses, balls inside the box (when the wall on that side is on) and not overlapping,
/// counts within kMaxBalls. A scene with savedFrom (a state a simulation saved) is exempt from
/// the inside-the-box and overlap rules, and its savedFrom is checked instead. Throws SceneError
/// naming `source` and the place.
void validateScene(const Scene& scene, std::string_view source);

/// For a scene with savedFrom that breaks the overlap or inside-the-box rule of hand-written
/// scenes: one line naming the worst case, e.g. "scene.json: saved from a running simulation:
/// balls[498] overlaps balls[406] by 10.1% of the smaller radius". Empty for any other scene.
/// The apps show it as a warning when they open a file.
std::string savedStateWarning(const Scene& scene, std::string_view source);

/// The per-ball rules of validateScene (not the overlap rule); `where` is e.g. "balls[3]".
/// Throws BallError (fooball/ball_problem.h), whose problem() says what is wrong.
void validateBall(const BallDef& ball, const Box& box, const Walls& walls, std::string_view where);

}  // namespace fooball
