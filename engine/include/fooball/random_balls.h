#pragma once

#include <cstddef>
#include <cstdint>

#include "fooball/scene.h"

namespace fooball {

/// The `random_balls` block of a scene file.
struct RandomBalls {
  std::size_t count = 0;
  double minRadius = 0.1;  ///< m
  double maxRadius = 0.3;  ///< m
  double minSpeed = 0.5;   ///< m/s
  double maxSpeed = 3.0;   ///< m/s
  double density = 1.0;    ///< kg/m², mass = density·π r²
  std::uint64_t seed = 1;
};

/// Appends `spec.count` balls to `scene` with uniform random radius, speed and direction.
/// New balls overlap neither each other nor the balls already in the scene, and lie inside the
/// box. The same scene and spec give the same balls on every platform (own RNG transform, no
/// std::uniform_real_distribution). O(N + box area / cell): balls go to distinct random cells of
/// a lattice of pitch 2·maxRadius, jittered inside their cell — no rejection loops.
/// Throws SceneError("random_balls.count: ...") when they cannot fit.
void addRandomBalls(Scene& scene, const RandomBalls& spec);

/// How many balls of radius up to `maxRadius` (> 0) addRandomBalls finds room for in `scene`
/// beside its balls when it places `count` (its lattice depends on the count): it refuses a
/// count above this. Not the limit on the number of balls, kMaxBalls.
std::size_t randomBallRoom(const Scene& scene, double maxRadius, std::size_t count);

}  // namespace fooball
