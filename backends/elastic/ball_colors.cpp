#include "ball_colors.h"

#include <algorithm>

namespace fooball::elastic {

namespace {

bool indexBefore(const std::pair<std::uint32_t, std::uint32_t>& exception, std::size_t index) {
  return exception.first < index;
}

}  // namespace

void BallColors::assign(std::span<const BallDef> balls) {
  exceptions_.clear();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (balls[i].color != defaultBallColor(i))
      exceptions_.emplace_back(static_cast<std::uint32_t>(i), balls[i].color);
  }
  exceptions_.shrink_to_fit();
}

std::uint32_t BallColors::operator[](std::size_t index) const {
  const auto it = std::lower_bound(exceptions_.begin(), exceptions_.end(), index, indexBefore);
  return it != exceptions_.end() && it->first == index ? it->second : defaultBallColor(index);
}

void BallColors::set(std::size_t index, std::uint32_t color) {
  const auto it = std::lower_bound(exceptions_.begin(), exceptions_.end(), index, indexBefore);
  const bool listed = it != exceptions_.end() && it->first == index;
  if (color == defaultBallColor(index)) {
    if (listed) exceptions_.erase(it);
  } else if (listed) {
    it->second = color;
  } else {
    exceptions_.insert(it, {static_cast<std::uint32_t>(index), color});
  }
}

}  // namespace fooball::elastic
