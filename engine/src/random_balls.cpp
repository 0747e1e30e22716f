#include "fooball/random_balls.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "fooball/scene_error.h"
#include "fooball/split_mix64.h"
#include "json_place.h"
#include "message_text.h"

namespace fooball {
namespace {

std::string rangeText(double low, double high) {
  std::string text = "[";
  text += exactNumberText(low);
  text += ", ";
  text += exactNumberText(high);
  text += ']';
  return text;
}

void checkSpec(const RandomBalls& spec, std::size_t existingBalls) {
  const Place top;
  const Place place = top.key("random_balls");
  if (spec.count > kMaxBalls - std::min(existingBalls, kMaxBalls)) {
    const std::string limit = std::to_string(kMaxBalls);
    if (existingBalls == 0) {
      failAt(place.key("count"),
             "must be at most " + limit + " (got " + std::to_string(spec.count) + ")");
    }
    failAt(place.key("count"), std::to_string(spec.count) + " random balls and " +
                                   std::to_string(existingBalls) +
                                   " explicit balls are more than the limit of " + limit);
  }
  const double minRadius = spec.minRadius;
  const double maxRadius = spec.maxRadius;
  if (!(std::isfinite(maxRadius) && 0.0 < minRadius && minRadius <= maxRadius)) {
    failAt(place.key("radius"),
           "must be [min, max] with 0 < min <= max (got " + rangeText(minRadius, maxRadius) + ")");
  }
  if (maxRadius > kMaxBoxSide) {
    failAt(place.key("radius"), "max must be at most " +
                                    std::to_string(static_cast<long long>(kMaxBoxSide)) +
                                    " m (got " + exactNumberText(maxRadius) + ")");
  }
  if (!(std::isfinite(spec.maxSpeed) && 0.0 <= spec.minSpeed && spec.minSpeed <= spec.maxSpeed)) {
    failAt(place.key("speed"), "must be [min, max] with 0 <= min <= max (got " +
                                   rangeText(spec.minSpeed, spec.maxSpeed) + ")");
  }
  const Place density = place.key("density");
  if (!(std::isfinite(spec.density) && spec.density > 0.0)) {
    failAt(density, "must be > 0 (got " + exactNumberText(spec.density) + ")");
  }
  for (const double radius : {minRadius, maxRadius}) {
    const double mass = diskMass(radius, spec.density);
    if (!(std::isfinite(mass) && mass > 0.0)) {
      failAt(density, "gives balls of radius " + exactNumberText(radius) + " m a mass of " +
                          exactNumberText(mass) + " kg");
    }
  }
}

/// The sites random balls go to: a grid of cells over the box, each at least a diameter wide,
/// one ball per cell. Balls in different cells cannot overlap, so no ball is ever retried.
struct Lattice {
  int columns = 0;
  int rows = 0;
  double cellWidth = 0.0;   ///< m, ≥ the largest diameter
  double cellHeight = 0.0;  ///< m

  std::size_t cellCount() const { return static_cast<std::size_t>(columns) * rows; }
};

Lattice latticeFor(const Box& box, double maxRadius, std::size_t ballsToPlace,
                   std::size_t existingBalls) {
  // Diameter-wide cells over a huge box would outnumber memory. Beyond a few cells per ball
  // extra cells only add empty sites, so there the cells grow instead; balls are spread over
  // their whole cell, so placement stays uniform over the box.
  const double maxCells =
      2.0 * static_cast<double>(ballsToPlace) + 4.0 * static_cast<double>(existingBalls) + 4096.0;
  const double pitch = std::max(2.0 * maxRadius, std::sqrt(box.width * box.height / maxCells));
  // Each factor ≤ side / pitch, so columns × rows ≤ box area / pitch² ≤ maxCells.
  const double columns = std::floor(std::min(box.width / pitch, maxCells));
  const double rows = std::floor(std::min(box.height / pitch, maxCells));
  if (columns < 1.0 || rows < 1.0) return {};
  return {static_cast<int>(columns), static_cast<int>(rows), box.width / columns,
          box.height / rows};
}

/// floor(value) clamped to [-1, count], so any finite or infinite coordinate maps to a cell
/// index or just outside the lattice.
int clampedIndex(double value, int count) {
  const double index = std::floor(value);
  if (!(index >= 0.0)) return -1;
  return index < count ? static_cast<int>(index) : count;
}

/// The lattice cells no existing ball reaches into. Each ball marks, row by row, the interval
/// of cells its disk meets, in a difference array: the cost is the rows a ball spans, not its
/// cells, so big balls stay cheap.
std::vector<std::uint32_t> freeSites(const Lattice& lattice, std::span<const BallDef> existing) {
  const auto stride = static_cast<std::size_t>(lattice.columns) + 1;
  std::vector<std::int32_t> coverage(stride * lattice.rows, 0);
  for (const BallDef& ball : existing) {
    const Vec2 p = ball.position;
    const double r = ball.radius;
    const int lowRow = std::max(0, clampedIndex((p.y - r) / lattice.cellHeight, lattice.rows));
    const int highRow =
        std::min(lattice.rows - 1, clampedIndex((p.y + r) / lattice.cellHeight, lattice.rows));
    for (int row = lowRow; row <= highRow; ++row) {
      const double bottom = row * lattice.cellHeight;
      const double dy = std::max({0.0, bottom - p.y, p.y - (bottom + lattice.cellHeight)});
      if (dy >= r) continue;
      const double halfWidth = std::sqrt(r * r - dy * dy);  // of the disk within this row
      const int lowColumn =
          std::max(0, clampedIndex((p.x - halfWidth) / lattice.cellWidth, lattice.columns));
      const int highColumn =
          std::min(lattice.columns - 1,
                   clampedIndex((p.x + halfWidth) / lattice.cellWidth, lattice.columns));
      if (lowColumn > highColumn) continue;
      ++coverage[row * stride + lowColumn];
      --coverage[row * stride + highColumn + 1];
    }
  }
  std::vector<std::uint32_t> sites;
  sites.reserve(lattice.cellCount());
  for (int row = 0; row < lattice.rows; ++row) {
    std::int32_t covered = 0;
    for (int column = 0; column < lattice.columns; ++column) {
      covered += coverage[row * stride + column];
      if (covered == 0) sites.push_back(static_cast<std::uint32_t>(row * lattice.columns + column));
    }
  }
  return sites;
}

/// A uniform direction without sin/cos, whose last bits differ between maths libraries: a point
/// uniform in the unit disk, drawn from the square around it (4/π draws on average), scaled to
/// length 1. This one short loop is per ball; placement itself never retries.
Vec2 randomDirection(SplitMix64& random) {
  for (;;) {
    const Vec2 point{random.between(-1.0, 1.0), random.between(-1.0, 1.0)};
    const double lengthSq = lengthSquared(point);
    if (lengthSq > 0.0 && lengthSq <= 1.0) return point / std::sqrt(lengthSq);
  }
}

}  // namespace

std::size_t randomBallRoom(const Scene& scene, double maxRadius, std::size_t count) {
  return freeSites(latticeFor(scene.box, maxRadius, count, scene.balls.size()), scene.balls).size();
}

void addRandomBalls(Scene& scene, const RandomBalls& spec) {
  checkSpec(spec, scene.balls.size());
  if (spec.count == 0) return;
  const Lattice lattice = latticeFor(scene.box, spec.maxRadius, spec.count, scene.balls.size());
  std::vector<std::uint32_t> sites = freeSites(lattice, scene.balls);
  if (sites.size() < spec.count) {
    const Place top;
    failAt(top.key("random_balls").key("count"),
           std::to_string(spec.count) + " balls of radius up to " +
               exactNumberText(spec.maxRadius) + " m do not fit: the box has room for at most " +
               std::to_string(sites.size()) +
               (scene.balls.empty() ? "" : " beside the balls already in it"));
  }

  SplitMix64 random(spec.seed);
  scene.balls.reserve(scene.balls.size() + spec.count);
  for (std::size_t k = 0; k < spec.count; ++k) {
    // A partial Fisher–Yates shuffle: the first k sites are the distinct cells chosen so far.
    std::swap(sites[k], sites[k + random.below(sites.size() - k)]);
    const double left = (sites[k] % lattice.columns) * lattice.cellWidth;
    const double bottom = (sites[k] / lattice.columns) * lattice.cellHeight;
    BallDef ball;
    ball.radius = random.between(spec.minRadius, spec.maxRadius);
    const double slackX = std::max(0.0, lattice.cellWidth - 2.0 * ball.radius);
    const double slackY = std::max(0.0, lattice.cellHeight - 2.0 * ball.radius);
    ball.position = {left + ball.radius + slackX * random.unit(),
                     bottom + ball.radius + slackY * random.unit()};
    ball.velocity = random.between(spec.minSpeed, spec.maxSpeed) * randomDirection(random);
    ball.mass = diskMass(ball.radius, spec.density);
    ball.color = defaultBallColor(scene.balls.size());
    scene.balls.push_back(ball);
  }
}

}  // namespace fooball
