#pragma once

#include <limits>

namespace fooball::testing {

/// A closed range [low, high].
struct Interval {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();

  constexpr bool contains(double value) const { return value >= low && value <= high; }
};

/// [centre − halfWidth, centre + halfWidth].
constexpr Interval around(double centre, double halfWidth) {
  return {centre - halfWidth, centre + halfWidth};
}

/// [−halfWidth, halfWidth]: a change that may go either way by as much.
constexpr Interval eitherWay(double halfWidth) {
  return around(0.0, halfWidth);
}

}  // namespace fooball::testing
