#pragma once

#include <cstddef>
#include <cstdint>

#include "fooball/scene.h"

namespace fooball {

/// The standard gas that benchmarks, the capacity tool and scaling tests share: `count` balls of
/// radius 0.1–0.2 m and speed 0.5–3 m/s, no gravity, all walls, in a 16:9 box sized so the balls
/// cover `packingFraction` of its area.
Scene standardGas(std::size_t count, double packingFraction, std::uint64_t seed = 1);

}  // namespace fooball
