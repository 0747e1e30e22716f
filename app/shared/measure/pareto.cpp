#include "pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fooball::measure {

std::vector<std::size_t> paretoFront(std::span<const CostAndError> points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::erase_if(order, [&](std::size_t i) {
    return std::isnan(points[i].cost) || std::isnan(points[i].error);
  });
  // By cost, then error: a point is on the front when it is more accurate than every cheaper one.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  double bestError = std::numeric_limits<double>::infinity();
  for (const std::size_t i : order) {
    if (points[i].error < bestError) {
      front.push_back(i);
      bestError = points[i].error;
    }
  }
  return front;
}

}  // namespace fooball::measure
