#include "event_cells.h"

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
  head_.assign(static_cast<std::size_t>(columns_ + 2) * static_cast<std::size_t>(rows_ + 2), kNone);
  members_.assign(ballCount, Membership{});
}

void EventCells::insert(std::uint32_t ball, Vec2 position) {
  members_[ball].column = clampedIndex(position.x, cellSide_[0], columns_);
  members_[ball].row = clampedIndex(position.y, cellSide_[1], rows_);
  link(ball);
}

void EventCells::cross(std::uint32_t ball, Side side) {
  unlink(ball);
  const int step = isLowerSide(side) ? -1 : 1;
  if (axisOf(side) == 0) {
    members_[ball].column += step;
  } else {
    members_[ball].row += step;
  }
  link(ball);
}

void EventCells::link(std::uint32_t ball) {
  const Membership& member = members_[ball];
  linkFirst(members_, ball, head_[cellIndex(member.column, member.row)]);
}

void EventCells::unlink(std::uint32_t ball) {
  const Membership& member = members_[ball];
  exact::unlink(members_, ball, head_[cellIndex(member.column, member.row)]);
}

}  // namespace fooball::exact
