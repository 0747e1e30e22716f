// CellGrid, the broadphase of the elastic backend and of the overlap metric. Its answers are
// combinatorial (which cell, which pairs), so every check is exact: against the cell a point
// claims to be in, and against a brute-force search over all pairs.

#include "fooball/cell_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <vector>

namespace fooball {
namespace {

constexpr double kWidth = 16.0;  // m
constexpr double kHeight = 9.0;  // m

std::vector<Vec2> randomPoints(std::size_t count, Vec2 low, Vec2 high, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(low.x, high.x);
  std::uniform_real_distribution<double> y(low.y, high.y);
  std::vector<Vec2> points(count);
  for (Vec2& p : points)
    p = {x(random), y(random)};
  return points;
}

/// Every point is in exactly one cell, the one cellOf() names; order() is a permutation of the
/// indices, sorted by cell.
void expectEveryPointInExactlyOneCell(const CellGrid& grid, std::span<const Vec2> points) {
  const int cellCount = grid.columns() * grid.rows();
  std::vector<int> timesSeen(points.size(), 0);
  std::size_t total = 0;
  for (int cell = 0; cell < cellCount; ++cell) {
    for (const std::uint32_t index : grid.pointsIn(cell)) {
      ASSERT_LT(index, points.size());
      ++timesSeen[index];
      ++total;
      EXPECT_EQ(grid.cellOf(points[index]), cell) << "point " << index;
    }
  }
  EXPECT_EQ(total, points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(timesSeen[i], 1) << "point " << i;

  const auto order = grid.order();
  ASSERT_EQ(order.size(), points.size());
  std::vector<std::uint32_t> sorted(order.begin(), order.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], i) << "order() is not a permutation";
  for (std::size_t i = 1; i < order.size(); ++i) {
    EXPECT_LE(grid.cellOf(points[order[i - 1]]), grid.cellOf(points[order[i]]))
        << "order() is not sorted by cell at position " << i;
  }
}

/// Every pair closer than the cell size is visited exactly once, no pair is visited twice and
/// no point is paired with itself. Brute force over all pairs: O(N²), fine for N ≤ a few 1000.
void expectEveryClosePairVisitedOnce(const CellGrid& grid, std::span<const Vec2> points) {
  const std::size_t count = points.size();
  std::vector<std::uint8_t> visits(count * count, 0);  // [min·count + max]; N ≤ 2,000 here
  std::size_t selfPairs = 0;
  std::size_t visitedTwice = 0;
  grid.forEachNearbyPair([&](std::uint32_t a, std::uint32_t b) {
    if (a == b) ++selfPairs;
    std::uint8_t& seen = visits[std::min(a, b) * count + std::max(a, b)];
    if (seen != 0) ++visitedTwice;
    seen = 1;
  });
  EXPECT_EQ(selfPairs, 0u);
  EXPECT_EQ(visitedTwice, 0u) << "pairs visited more than once";

  const double reach = grid.cellSize();
  std::size_t missed = 0;
  for (std::size_t a = 0; a < count; ++a) {
    for (std::size_t b = a + 1; b < count; ++b) {
      if (lengthSquared(points[a] - points[b]) < reach * reach && visits[a * count + b] == 0) {
        if (++missed <= 5) ADD_FAILURE() << "close pair (" << a << ", " << b << ") not visited";
      }
    }
  }
  EXPECT_EQ(missed, 0u);
}

TEST(CellGrid, EveryPointLandsInExactlyOneCellAndOrderIsAPermutation) {
  const auto points = randomPoints(1000, {0.0, 0.0}, {kWidth, kHeight}, 1);
  CellGrid grid;
  grid.build(points, kWidth, kHeight, 0.4);
  EXPECT_GT(grid.columns() * grid.rows(), 100) << "the test should spread points over many cells";
  expectEveryPointInExactlyOneCell(grid, points);
}

TEST(CellGrid, PointsOutsideTheRectangleGoToTheBorderCells) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec2> points = {
      {-3.0, 4.5}, {1e300, 4.5}, {8.0, -1e300}, {8.0, 1e9},      {-kInf, kInf}, {kInf, -kInf},
      {kNaN, 4.5}, {8.0, kNaN},  {kNaN, kNaN},  {-0.0, -1e-300}, {0.0, 0.0},    {kWidth, kHeight}};
  CellGrid grid;
  grid.build(points, kWidth, kHeight, 1.0);
  const int lastColumn = grid.columns() - 1;
  const int lastRow = grid.rows() - 1;
  const auto columnOf = [&](Vec2 p) { return grid.cellColumn(grid.cellOf(p)); };
  const auto rowOf = [&](Vec2 p) { return grid.cellRow(grid.cellOf(p)); };

  EXPECT_EQ(columnOf(points[0]), 0);
  EXPECT_EQ(rowOf(points[0]), rowOf({0.5, 4.5}));
  EXPECT_EQ(columnOf(points[1]), lastColumn);
  EXPECT_EQ(rowOf(points[2]), 0);
  EXPECT_EQ(rowOf(points[3]), lastRow);
  EXPECT_EQ(columnOf(points[4]), 0);
  EXPECT_EQ(rowOf(points[4]), lastRow);
  EXPECT_EQ(columnOf(points[5]), lastColumn);
  EXPECT_EQ(rowOf(points[5]), 0);
  EXPECT_EQ(grid.cellOf(points[10]), 0);
  EXPECT_EQ(grid.cellOf(points[11]), lastRow * grid.columns() + lastColumn)
      << "the far corner belongs to the last cell";
  // NaN has no side; it must still land in a real cell (no UB in the float→int cast).
  for (const Vec2 p : points) {
    EXPECT_GE(grid.cellOf(p), 0);
    EXPECT_LT(grid.cellOf(p), grid.columns() * grid.rows());
  }
  expectEveryPointInExactlyOneCell(grid, points);
}

TEST(CellGrid, CellsAreAtLeastTheAskedSizeAndTheirCountIsCappedByThePointCount) {
  const auto points = randomPoints(100, {0.0, 0.0}, {kWidth, kHeight}, 2);
  CellGrid grid;
  grid.build(points, kWidth, kHeight, 0.5);
  EXPECT_GE(grid.cellSize(), 0.5);
  EXPECT_LE(grid.columns() * grid.cellSize(), kWidth * (1.0 + 1e-12)) << "cells fit in the box";
  EXPECT_LE(grid.rows() * grid.cellSize(), kHeight * (1.0 + 1e-12));

  // A tiny asked size would give millions of cells for 100 points; the cap keeps ~2 per point.
  grid.build(points, kWidth, kHeight, 1e-6);
  EXPECT_LE(grid.columns() * grid.rows(), 200);
  EXPECT_GE(grid.columns() * grid.rows(), 50) << "but not so few that the grid is useless";
  expectEveryPointInExactlyOneCell(grid, points);
  expectEveryClosePairVisitedOnce(grid, points);

  // Cells larger than the box: a single cell holding everything.
  grid.build(points, kWidth, kHeight, 100.0);
  EXPECT_EQ(grid.columns(), 1);
  EXPECT_EQ(grid.rows(), 1);
  expectEveryPointInExactlyOneCell(grid, points);
  expectEveryClosePairVisitedOnce(grid, points);
}

TEST(CellGrid, ForEachNearbyPairVisitsEveryPairCloserThanTheCellSizeExactlyOnce) {
  CellGrid grid;
  {
    SCOPED_TRACE("uniform");
    const auto points = randomPoints(2000, {0.0, 0.0}, {kWidth, kHeight}, 3);
    grid.build(points, kWidth, kHeight, 0.3);
    expectEveryPointInExactlyOneCell(grid, points);
    expectEveryClosePairVisitedOnce(grid, points);
  }
  {
    SCOPED_TRACE("clustered: a dense clump in one corner and a sparse rest");
    auto points = randomPoints(400, {15.5, 8.5}, {kWidth, kHeight}, 4);
    const auto rest = randomPoints(400, {0.0, 0.0}, {kWidth, kHeight}, 5);
    points.insert(points.end(), rest.begin(), rest.end());
    grid.build(points, kWidth, kHeight, 0.2);
    expectEveryPointInExactlyOneCell(grid, points);
    expectEveryClosePairVisitedOnce(grid, points);
  }
  {
    SCOPED_TRACE("all at one point");
    const std::vector<Vec2> points(150, Vec2{3.0, 3.0});
    grid.build(points, kWidth, kHeight, 0.2);
    expectEveryClosePairVisitedOnce(grid, points);
  }
  {
    SCOPED_TRACE("walls off: many points outside the rectangle");
    const auto points = randomPoints(1500, {-4.0, -4.0}, {kWidth + 4.0, kHeight + 4.0}, 6);
    grid.build(points, kWidth, kHeight, 0.3);
    expectEveryPointInExactlyOneCell(grid, points);
    expectEveryClosePairVisitedOnce(grid, points);
  }
  {
    SCOPED_TRACE("pairs across every kind of cell boundary");
    // A 4 × 4 m box with 8 points gets 1 m cells (16 cells, the cap for few points). Pairs
    // across a vertical, a horizontal, the main and the anti diagonal boundary (the last needs
    // the (−1, +1) neighbour offset).
    const std::vector<Vec2> points = {{0.99, 0.5},  {1.01, 0.5},  {2.5, 1.99},  {2.5, 2.01},
                                      {0.99, 2.99}, {1.01, 3.01}, {3.01, 2.99}, {2.99, 3.01}};
    grid.build(points, 4.0, 4.0, 1.0);
    ASSERT_EQ(grid.cellSize(), 1.0);
    expectEveryClosePairVisitedOnce(grid, points);
  }
  {
    SCOPED_TRACE("empty and single");
    grid.build(std::span<const Vec2>{}, kWidth, kHeight, 0.3);
    EXPECT_TRUE(grid.order().empty());
    int visits = 0;
    grid.forEachNearbyPair([&](std::uint32_t, std::uint32_t) { ++visits; });
    EXPECT_EQ(visits, 0);
    const std::vector<Vec2> one = {{1.0, 1.0}};
    grid.build(one, kWidth, kHeight, 0.3);
    expectEveryPointInExactlyOneCell(grid, one);
    grid.forEachNearbyPair([&](std::uint32_t, std::uint32_t) { ++visits; });
    EXPECT_EQ(visits, 0);
  }
}

TEST(CellGrid, RebuildingWithFewerPointsForgetsTheOldOnes) {
  CellGrid grid;
  const auto many = randomPoints(2000, {0.0, 0.0}, {kWidth, kHeight}, 7);
  grid.build(many, kWidth, kHeight, 0.3);
  const auto few = randomPoints(50, {0.0, 0.0}, {kWidth, kHeight}, 8);
  grid.build(few, kWidth, kHeight, 0.3);
  expectEveryPointInExactlyOneCell(grid, few);
  expectEveryClosePairVisitedOnce(grid, few);

  grid.build(std::span<const Vec2>{}, kWidth, kHeight, 0.3);
  for (int cell = 0; cell < grid.columns() * grid.rows(); ++cell)
    EXPECT_TRUE(grid.pointsIn(cell).empty()) << "cell " << cell;

  grid.build(many, kWidth, kHeight, 0.3);
  expectEveryPointInExactlyOneCell(grid, many);
}

TEST(CellGrid, CoordinateArraysGiveTheSameGridAsPoints) {
  const auto points = randomPoints(500, {-1.0, -1.0}, {kWidth + 1.0, kHeight + 1.0}, 9);
  std::vector<double> xs, ys;
  for (const Vec2 p : points) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  CellGrid fromPoints, fromArrays;
  fromPoints.build(points, kWidth, kHeight, 0.4);
  fromArrays.build(xs, ys, kWidth, kHeight, 0.4);
  EXPECT_EQ(fromArrays.columns(), fromPoints.columns());
  EXPECT_EQ(fromArrays.rows(), fromPoints.rows());
  EXPECT_EQ(fromArrays.cellSize(), fromPoints.cellSize());
  const auto a = fromPoints.order();
  const auto b = fromArrays.order();
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
}

}  // namespace
}  // namespace fooball
