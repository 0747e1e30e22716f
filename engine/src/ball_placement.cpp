#include "fooball/ball_placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
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

/// New balls' size range: that of the balls in `room`, or the default one in an empty box.
RandomBalls newBallSpec(const Scene& room) {
  RandomBalls spec;
  spec.minRadius = kDefaultMinRadius;
  spec.maxRadius = kDefaultMaxRadius;
  if (!room.balls.empty()) {
    const auto [smallest, largest] =
        std::minmax_element(room.balls.begin(), room.balls.end(),
                            [](const BallDef& a, const BallDef& b) { return a.radius < b.radius; });
    spec.minRadius = smallest->radius;
    spec.maxRadius = largest->radius;
  }
  return spec;
}

/// The box's area that `runs` runs' balls in `room` leave free (m²).
double freeArea(const Scene& room, std::size_t runs) {
  // Every run holds the same balls, so they cover the area once: 1/runs of the room's sum.
  double coveredArea = 0.0;
  for (const BallDef& ball : room.balls)
    coveredArea += std::numbers::pi * ball.radius * ball.radius;
  return room.box.width * room.box.height - coveredArea / double(std::max<std::size_t>(runs, 1));
}

/// At what scale of `maxRadius` placeNewBalls places `count` new balls in `room`, or none when
/// they do not fit even at the smallest scale it tries, which `tried` then holds.
std::optional<double> fittingScale(const Scene& room, std::size_t runs, double maxRadius,
                                   std::size_t count, double& tried) {
  // Sized like the balls there if they fit; otherwise smaller, as the free area allows: balls
  // go one per lattice cell of side 2·maxRadius, so maxRadius ≈ √(free area / count) / 2.
  const double fittingRadius =
      kLatticeFill * 0.5 * std::sqrt(std::max(freeArea(room, runs), 0.0) / double(count));
  double scale = std::min(1.0, fittingRadius / maxRadius);
  tried = kMinScale;
  if (scale < kMinScale) return std::nullopt;
  if (count > kMaxBalls - std::min(room.balls.size(), kMaxBalls)) return std::nullopt;
  for (int attempt = 0;; ++attempt) {
    tried = scale;
    if (randomBallRoom(room, scale * maxRadius, count) >= count) return scale;
    if (attempt == kMaxAttempts || scale * kShrinkPerAttempt < kMinScale) return std::nullopt;
    scale *= kShrinkPerAttempt;
  }
}

}  // namespace

PlacedBalls placeNewBalls(const Scene& room, std::size_t runs, std::size_t count,
                          std::size_t firstIndex, std::uint64_t seed) {
  PlacedBalls placed;
  if (count == 0) return placed;
  RandomBalls spec = newBallSpec(room);
  double tried = 1.0;
  const std::optional<double> scale = fittingScale(room, runs, spec.maxRadius, count, tried);
  if (!scale) throw doesNotFit(count, tried);
  placed.scale = *scale;
  spec.count = count;
  spec.seed = seed;
  spec.minRadius *= placed.scale;
  spec.maxRadius *= placed.scale;
  Scene trial = room;
  addRandomBalls(trial, spec);
  placed.balls.assign(trial.balls.begin() + static_cast<std::ptrdiff_t>(room.balls.size()),
                      trial.balls.end());
  for (std::size_t i = 0; i < placed.balls.size(); ++i)
    placed.balls[i].color = defaultBallColor(firstIndex + i);
  return placed;
}

std::size_t mostNewBallsThatFit(const Scene& room, std::size_t runs) {
  const double maxRadius = newBallSpec(room).maxRadius;
  double tried = 1.0;
  const auto fits = [&](std::size_t count) {
    return fittingScale(room, runs, maxRadius, count, tried).has_value();
  };
  // Beyond this count even the smallest balls get too little area each (fittingScale's first
  // test), so it does not fit; nor does one more than the limit on balls.
  const double areaBound = std::max(freeArea(room, runs), 0.0) *
                           std::pow(kLatticeFill * 0.5 / (kMinScale * maxRadius), 2.0);
  std::size_t fitting = 0;  // fits (nothing to place)
  std::size_t tooMany = std::min(kMaxBalls - std::min(room.balls.size(), kMaxBalls) + 1,
                                 static_cast<std::size_t>(std::min(areaBound, 4.0e18)) + 2);
  while (tooMany - fitting > 1) {
    const std::size_t middle = fitting + (tooMany - fitting) / 2;
    (fits(middle) ? fitting : tooMany) = middle;
  }
  return fitting;
}

}  // namespace fooball
