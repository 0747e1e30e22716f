#include "fooball/ball_placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fooball/random_balls.h"
#include "fooball/scene_error.h"

namespace fooball {

namespace {

/// New balls get the size range of the balls already there, or this one in an empty box.
constexpr double kDefaultMinRadius = 0.1;  // m
constexpr double kDefaultMaxRadius = 0.3;  // m
/// When they do not fit at that size they shrink, at most to this fraction of it…
constexpr double kMinScale = 0.01;
/// …aiming at lattice cells this much wider than a ball, shrinking further if need be.
constexpr double kLatticeFill = 0.8;
constexpr double kShrinkPerAttempt = 0.8;
constexpr int kMaxAttempts = 8;

SceneError doesNotFit(std::size_t count, double scale) {
  return SceneError("cannot add " + std::to_string(count) + " balls: they do not fit even at " +
                    std::to_string(std::lround(100.0 * scale)) +
                    " % of the size of the balls there");
}

}  // namespace

PlacedBalls placeNewBalls(const Scene& room, std::size_t runs, std::size_t count,
                          std::size_t firstIndex, std::uint64_t seed) {
  PlacedBalls placed;
  if (count == 0) return placed;
  RandomBalls spec;
  spec.count = count;
  spec.seed = seed;
  spec.minRadius = kDefaultMinRadius;
  spec.maxRadius = kDefaultMaxRadius;
  double freeArea = room.box.width * room.box.height;
  if (!room.balls.empty()) {
    const auto [smallest, largest] =
        std::minmax_element(room.balls.begin(), room.balls.end(),
                            [](const BallDef& a, const BallDef& b) { return a.radius < b.radius; });
    spec.minRadius = smallest->radius;
    spec.maxRadius = largest->radius;
  }
  // Sized like the balls there if they fit; otherwise smaller, as the free area allows: balls
  // go one per lattice cell of side 2·maxRadius, so maxRadius ≈ √(free area / count) / 2.
  // Every run holds the same balls, so they cover the area once: 1/runs of the room's sum.
  double coveredArea = 0.0;
  for (const BallDef& ball : room.balls)
    coveredArea += std::numbers::pi * ball.radius * ball.radius;
  freeArea -= coveredArea / double(std::max<std::size_t>(runs, 1));
  const double fittingRadius =
      kLatticeFill * 0.5 * std::sqrt(std::max(freeArea, 0.0) / double(count));
  placed.scale = std::min(1.0, fittingRadius / spec.maxRadius);
  if (placed.scale < kMinScale) throw doesNotFit(count, kMinScale);
  for (int attempt = 0;; ++attempt) {
    RandomBalls scaled = spec;
    scaled.minRadius *= placed.scale;
    scaled.maxRadius *= placed.scale;
    Scene trial = room;
    try {
      addRandomBalls(trial, scaled);
      placed.balls.assign(trial.balls.begin() + static_cast<std::ptrdiff_t>(room.balls.size()),
                          trial.balls.end());
      for (std::size_t i = 0; i < placed.balls.size(); ++i)
        placed.balls[i].color = defaultBallColor(firstIndex + i);
      return placed;
    } catch (const SceneError&) {
      if (attempt == kMaxAttempts || placed.scale * kShrinkPerAttempt < kMinScale) {
        throw doesNotFit(count, placed.scale);
      }
      placed.scale *= kShrinkPerAttempt;
    }
  }
}

}  // namespace fooball
