#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fooball/scene.h"

namespace fooball {

/// Balls added to a running scene (the ball-count spinner), and how they were sized.
struct PlacedBalls {
  std::vector<BallDef> balls;
  /// Their size relative to the balls already there (1: the same size range).
  double scale = 1.0;
};

/// `count` new balls clear of every ball in `room`, which holds the balls of `runs` runs at
/// once (the runs diverge, and a new ball must clear each run's), sized like the balls there — or
/// smaller, as the free area allows, down to 1% of that size. Reproducible from `seed`. New balls
/// get the colour the format gives their index, counted from `firstIndex`. Throws SceneError when
/// they do not fit even so.
PlacedBalls placeNewBalls(const Scene& room, std::size_t runs, std::size_t count,
                          std::size_t firstIndex, std::uint64_t seed);

/// The most new balls placeNewBalls places in `room` (its runs' balls, as there): it throws for
/// one more. What fits depends only on the count, not on the seed. O(log(count) × box cells).
std::size_t mostNewBallsThatFit(const Scene& room, std::size_t runs);

}  // namespace fooball
