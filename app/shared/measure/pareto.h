#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fooball::measure {

/// A method's price and what it gets wrong; lower is better for both.
struct CostAndError {
  double cost = 0.0;
  double error = 0.0;
};

/// The Pareto front: indices of the points that no other point matches or beats in both cost and
/// error (of equal points, the first), by ascending cost. Points with a NaN are never on it.
std::vector<std::size_t> paretoFront(std::span<const CostAndError> points);

}  // namespace fooball::measure
