#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "fooball/backend.h"

namespace fooball::testing {

/// A backend's balls as readState reports them, in scene order.
struct State {
  std::vector<Vec2> positions;   ///< m
  std::vector<Vec2> velocities;  ///< m/s
};

inline std::vector<Vec2> copyOf(std::span<const Vec2> values) {
  return {values.begin(), values.end()};
}

/// Steps `backend` for `seconds` (rounded to whole steps of `dt`, s) without forces.
inline void runFor(Backend& backend, double seconds, double dt = kDefaultDt) {
  const auto steps = static_cast<int>(std::lround(seconds / dt));
  for (int i = 0; i < steps; ++i)
    backend.step(dt, {});
}

inline State readState(const Backend& backend) {
  State state{std::vector<Vec2>(backend.ballCount()), std::vector<Vec2>(backend.ballCount())};
  backend.readState(state.positions, state.velocities);
  return state;
}

}  // namespace fooball::testing
