#include "exact/event_cells.h"

#include <algorithm>
#include <cmath>

namespace fooball::exact {

namespace {

int clampedIndex(double coordinate, double cellSide, int count) {
  const double index = std::floor(coordinate / cellSide);
  if (!(index > 0.0)) return 0;
  return index >= count - 1 ? count - 1 : static_cast<int>(index);
}

}  // namespace

void EventCells::configure(double width, double height, double minCellSize, std::size_t ballCount) {
  const double maxCells = 4.0 * static_cast<double>(ballCount) + 16.0;
  const double side = std::max(
      {minCellSize, std::sqrt(width * height / maxCells), width / maxCells, height / maxCells});
  columns_ = static_cast<int>(std::max(1.0, std::floor(width / side)));
  rows_ = static_cast<int>(std::max(1.0, std::floor(height / side)));
  cellSide_[0] = width / columns_;
  cellSide_[1] = height / rows_;
  head_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_), kNone);
  next_.assign(ballCount, kNone);
  previous_.assign(ballCount, kNone);
  column_.assign(ballCount, 0);
  row_.assign(ballCount, 0);
}

void EventCells::insert(std::uint32_t ball, Vec2 position) {
  column_[ball] = clampedIndex(position.x, cellSide_[0], columns_);
  row_[ball] = clampedIndex(position.y, cellSide_[1], rows_);
  link(ball);
}

void EventCells::cross(std::uint32_t ball, Side side) {
  unlink(ball);
  const int step = isLowerSide(side) ? -1 : 1;
  if (axisOf(side) == 0) {
    column_[ball] += step;
  } else {
    row_[ball] += step;
  }
  link(ball);
}

void EventCells::link(std::uint32_t ball) {
  std::uint32_t& head = head_[row_[ball] * columns_ + column_[ball]];
  previous_[ball] = kNone;
  next_[ball] = head;
  if (head != kNone) previous_[head] = ball;
  head = ball;
}

void EventCells::unlink(std::uint32_t ball) {
  if (previous_[ball] != kNone) {
    next_[previous_[ball]] = next_[ball];
  } else {
    head_[row_[ball] * columns_ + column_[ball]] = next_[ball];
  }
  if (next_[ball] != kNone) previous_[next_[ball]] = previous_[ball];
}

}  // namespace fooball::exact
