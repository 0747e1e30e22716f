#include "fooball/ball_problem.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fooball {
namespace {

std::optional<BallProblem> notFinite(double value, std::string_view quantity, int component) {
  if (std::isfinite(value)) return std::nullopt;
  return BallProblem{BallProblem::Kind::NotFinite, quantity, component, value, {}, 0};
}

std::optional<BallProblem> notFinite(Vec2 value, std::string_view quantity) {
  if (auto x = notFinite(value.x, quantity, 0)) return x;
  return notFinite(value.y, quantity, 1);
}

std::optional<BallProblem> notPositive(double value, std::string_view quantity) {
  if (auto problem = notFinite(value, quantity, -1)) return problem;
  if (value > 0.0) return std::nullopt;
  return BallProblem{BallProblem::Kind::NotPositive, quantity, -1, value, {}, 0};
}

/// m past `wall`, if more than the contact slop of the ball's radius (m).
std::optional<BallProblem> crossesWall(double depth, double radius, std::string_view wall) {
  if (!(depth > kContactSlop * radius)) return std::nullopt;
  return BallProblem{BallProblem::Kind::CrossesWall, "position", -1, depth, wall, 0};
}

/// "x position", "radius": the quantity as a sentence names it.
std::string quantityWords(const BallProblem& problem) {
  const std::string axis = problem.component == 0 ? "x " : problem.component == 1 ? "y " : "";
  if (problem.quantity == "color") return "colour";
  return axis + std::string(problem.quantity);
}

}  // namespace

std::string plainWords(const BallProblem& problem) {
  switch (problem.kind) {
    case BallProblem::Kind::NotFinite:
      return "The " + quantityWords(problem) + " must be a finite number.";
    case BallProblem::Kind::NotPositive:
      return "The " + quantityWords(problem) + " must be more than 0.";
    case BallProblem::Kind::TooLarge:
      return "The " + quantityWords(problem) + " must be at most " +
             std::to_string(static_cast<long long>(kMaxBoxSide)) + " m.";
    case BallProblem::Kind::NotAColour:
      return "The colour must be a 24-bit RGB colour.";
    case BallProblem::Kind::CrossesWall:
      return "The ball would stick out of the box through the " + std::string(problem.wall) +
             " wall.";
    case BallProblem::Kind::Overlaps:
      // Whole percent: the depth is beyond the slop (5%), so it never rounds to 0.
      return "The ball would overlap ball " + std::to_string(problem.otherBall) + " (by " +
             std::to_string(std::lround(100.0 * problem.value)) + "% of the smaller radius).";
  }
  return {};
}

std::optional<BallProblem> findValueProblem(const BallDef& ball) {
  if (auto problem = notFinite(ball.position, "position")) return problem;
  if (auto problem = notFinite(ball.velocity, "velocity")) return problem;
  if (auto problem = notPositive(ball.radius, "radius")) return problem;
  if (ball.radius > kMaxBoxSide) {
    return BallProblem{BallProblem::Kind::TooLarge, "radius", -1, ball.radius, {}, 0};
  }
  if (auto problem = notPositive(ball.mass, "mass")) return problem;
  if (ball.color > 0xffffffu) {
    return BallProblem{BallProblem::Kind::NotAColour, "color", -1, double(ball.color), {}, 0};
  }
  return std::nullopt;
}

std::optional<BallProblem> findBallProblem(const BallDef& ball, const Box& box,
                                           const Walls& walls) {
  if (auto problem = findValueProblem(ball)) return problem;
  const double r = ball.radius;
  const Vec2 p = ball.position;
  std::optional<BallProblem> problem;
  if (walls.left && !problem) problem = crossesWall(r - p.x, r, "left");
  if (walls.right && !problem) problem = crossesWall(p.x + r - box.width, r, "right");
  if (walls.bottom && !problem) problem = crossesWall(r - p.y, r, "bottom");
  if (walls.top && !problem) problem = crossesWall(p.y + r - box.height, r, "top");
  return problem;
}

std::optional<BallProblem> findOverlapProblem(const BallDef& ball, std::span<const Vec2> positions,
                                              std::span<const double> radii,
                                              std::optional<std::size_t> skip) {
  std::optional<BallProblem> deepest;
  for (std::size_t other = 0; other < positions.size(); ++other) {
    if (other == skip) continue;
    const double smaller = std::min(ball.radius, radii[other]);
    const double depth = ball.radius + radii[other] - length(ball.position - positions[other]);
    if (depth > kContactSlop * smaller && (!deepest || depth / smaller > deepest->value)) {
      deepest =
          BallProblem{BallProblem::Kind::Overlaps, "position", -1, depth / smaller, {}, other};
    }
  }
  return deepest;
}

}  // namespace fooball
