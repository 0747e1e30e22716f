// The value rules of the scene format, applied to in-memory scenes: the reader checks JSON
// types, these check what the numbers mean, so a scene built in code or saved by a backend
// meets the same rules as one read from a file. Where DESIGN.md is silent:
// - radius is at most kMaxBoxSide (a bigger ball fits no box, and its area would overflow);
// - the overlap rule holds only while ball_collisions is on: with it off, balls pass through
//   each other, and a state saved mid-pass must load back;
// - a scene with saved_from keeps every rule but the overlap and inside-the-box ones: whatever a
//   running simulation produced must load back exactly (savedStateWarning reports the worst);
//   saved_from's own values are checked like the rest (finite time >= 0, finite options).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "fooball/ball_problem.h"
#include "fooball/scene_file.h"
#include "message_text.h"
#include "overlap_search.h"
#include "scene_checks.h"

namespace fooball {
namespace {

std::string maxBoxSideText() {
  return std::to_string(static_cast<long long>(kMaxBoxSide));
}

std::string slopPercentText() {
  return roundedNumberText(100.0 * kContactSlop);
}

void checkFinite(double value, const Place& place) {
  if (!std::isfinite(value)) failAt(place, "must be finite (got " + exactNumberText(value) + ")");
}

void checkFinite(Vec2 value, const Place& place) {
  checkFinite(value.x, place.index(0));
  checkFinite(value.y, place.index(1));
}

void checkPositive(double value, const Place& place) {
  checkFinite(value, place);
  if (!(value > 0.0)) failAt(place, "must be > 0 (got " + exactNumberText(value) + ")");
}

void checkLength(double value, const Place& place) {
  checkPositive(value, place);
  if (value > kMaxBoxSide) {
    failAt(place,
           "must be at most " + maxBoxSideText() + " m (got " + exactNumberText(value) + ")");
  }
}

void checkBox(const Box& box, const Place& place) {
  checkLength(box.width, place.key("width"));
  checkLength(box.height, place.key("height"));
}

void checkWorld(const WorldSettings& world) {
  const Place top;
  checkFinite(world.gravity, top.key("gravity"));
  const Place airResistance = top.key("air_resistance");
  checkFinite(world.airResistance, airResistance);
  if (world.airResistance < 0.0) {
    failAt(airResistance, "must be >= 0 (got " + exactNumberText(world.airResistance) + ")");
  }
}

/// The scene format's words for a ball's problem (the app has its own: plainWords).
std::string reasonText(const BallProblem& problem) {
  const std::string got = " (got " + exactNumberText(problem.value) + ")";
  switch (problem.kind) {
    case BallProblem::Kind::NotFinite:
      return "must be finite" + got;
    case BallProblem::Kind::NotPositive:
      return "must be > 0" + got;
    case BallProblem::Kind::TooLarge:
      return "must be at most " + maxBoxSideText() + " m" + got;
    case BallProblem::Kind::NotAColour: {
      std::array<char, 16> hex{};
      std::snprintf(hex.data(), hex.size(), "0x%x", static_cast<unsigned>(problem.value));
      return "must be 0xRRGGBB (got " + std::string(hex.data()) + ")";
    }
    case BallProblem::Kind::CrossesWall:
      return "the ball crosses the " + std::string(problem.wall) + " wall by " +
             roundedNumberText(problem.value) + " m, more than " + slopPercentText() +
             "% of its radius";
    case BallProblem::Kind::Overlaps:
      return "overlaps balls[" + std::to_string(problem.otherBall) + "] by " +
             roundedNumberText(100.0 * problem.value) + "% of the smaller radius (the limit is " +
             slopPercentText() + "%)";
  }
  return {};
}

/// "balls[3].position[0]: must be finite (got nan)": at the place of the value, or of the ball
/// for an overlap.
std::string placedText(const Place& ball, const BallProblem& problem) {
  if (problem.kind == BallProblem::Kind::Overlaps) return ball.text() + ": " + reasonText(problem);
  const Place quantity = ball.key(problem.quantity);
  const std::string place = problem.component >= 0
                                ? quantity.index(std::size_t(problem.component)).text()
                                : quantity.text();
  return place + ": " + reasonText(problem);
}

/// The rules a ball meets wherever it is: finite, positive sizes and mass, a 24-bit colour.
void checkBallValues(const BallDef& ball, const Place& place) {
  if (const auto problem = findValueProblem(ball)) throw SceneError(placedText(place, *problem));
}

bool isSpecNameCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

void checkSavedFrom(const SavedFrom& from, const Place& place) {
  checkSpecName(from.backend, place.key("backend"), "a backend name");
  const Place options = place.key("options");
  for (const auto& [name, value] : from.options) {
    checkSpecName(name, options, "an option name");
    checkFinite(value, options.key(name));
  }
  const Place time = place.key("time");
  checkFinite(from.time, time);
  if (from.time < 0.0) failAt(time, "must be >= 0 (got " + exactNumberText(from.time) + ")");
}

}  // namespace

void checkSpecName(std::string_view name, const Place& place, std::string_view what) {
  if (name.empty() || name.size() > kMaxSpecNameBytes ||
      !std::all_of(name.begin(), name.end(), isSpecNameCharacter)) {
    failAt(place, "must be " + std::string(what) + " of 1 to " + std::to_string(kMaxSpecNameBytes) +
                      " letters, digits, '_' or '-' (got " + quotedText(name) + ")");
  }
}

void checkBall(const BallDef& ball, const Box& box, const Walls& walls, const Place& place) {
  if (const auto problem = findBallProblem(ball, box, walls)) {
    throw SceneError(placedText(place, *problem));
  }
}

void checkScene(const Scene& scene) {
  const Place top;
  checkBox(scene.box, top.key("box"));
  checkWorld(scene.world);
  if (scene.dt) checkPositive(*scene.dt, top.key("dt"));
  const Place balls = top.key("balls");
  if (scene.balls.size() > kMaxBalls) {
    failAt(balls, "has " + std::to_string(scene.balls.size()) + " balls, more than the limit of " +
                      std::to_string(kMaxBalls));
  }
  const bool saved = scene.savedFrom.has_value();
  if (saved) checkSavedFrom(*scene.savedFrom, top.key("saved_from"));
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const Place ball = balls.index(i);
    if (saved) {
      checkBallValues(scene.balls[i], ball);
    } else {
      checkBall(scene.balls[i], scene.box, scene.world.walls, ball);
    }
  }
  if (saved || !scene.world.ballCollisions) return;
  if (const auto overlap = findDeepOverlap(scene.balls, kContactSlop)) {
    BallProblem problem;
    problem.kind = BallProblem::Kind::Overlaps;
    problem.value = overlap->depthFraction;
    problem.otherBall = overlap->first;
    throw SceneError(placedText(balls.index(overlap->second), problem));
  }
}

void validateScene(const Scene& scene, std::string_view source) {
  try {
    checkScene(scene);
  } catch (const SceneError& error) {
    throw SceneError(withSource(source, error.what()));
  }
}

void validateBall(const BallDef& ball, const Box& box, const Walls& walls, std::string_view where) {
  if (const auto problem = findBallProblem(ball, box, walls)) {
    throw BallError(placedText(Place(where), *problem), *problem);
  }
}

}  // namespace fooball
