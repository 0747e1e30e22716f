// The elastic pair search's lane tests (elastic/pair_collisions.h): the AVX2 test, four lanes per
// instruction, resolves the same pairs in the same order as the scalar one, so the balls come out
// the same bits — in dense scenes full of overlaps, with coincident centres, a NaN and a cell too
// crowded for the usual neighbour copies.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "common/cell_lists.h"
#include "elastic/balls.h"
#include "elastic/pair_collisions.h"

namespace fooball::elastic {
namespace {

constexpr double kWidth = 20.0;     // m
constexpr double kHeight = 15.0;    // m
constexpr double kMaxRadius = 0.2;  // m

/// 2'000 balls of r = 0.1–0.2 m dropped at random into 20 m × 15 m (φ ≈ 0.5, so about a third
/// overlap a neighbour), masses 0.1–10 kg, speeds up to 3 m/s; then two balls on one centre, 40
/// in one cell and 5 near the origin, and if `withNaN`, one ball at x = NaN (in cell 0, beside
/// those 5).
std::vector<Ball> denseBalls(std::uint64_t seed, bool withNaN) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ball> balls;
  for (int i = 0; i < 2000; ++i) {
    balls.push_back({kWidth * unit(random), kHeight * unit(random), 6.0 * unit(random) - 3.0,
                     6.0 * unit(random) - 3.0, 0.1 + 0.1 * unit(random), 0.1 + 9.9 * unit(random)});
  }
  balls[1].x = balls[0].x;
  balls[1].y = balls[0].y;
  if (withNaN) balls[2].x = std::numeric_limits<double>::quiet_NaN();
  for (int i = 3; i < 8; ++i) {
    balls[i].x = 0.5 * unit(random);
    balls[i].y = 0.5 * unit(random);
  }
  for (int i = 10; i < 50; ++i) {
    balls[i].x = 10.0 + 0.3 * unit(random);
    balls[i].y = 7.0 + 0.3 * unit(random);
  }
  return balls;
}

/// The grid collideRows searches, built on the balls' centres with one worker.
common::CellLists cellsFor(const std::vector<Ball>& balls) {
  common::CellLists cells;
  cells.layout(balls.size(), kWidth, kHeight, 2.0 * kMaxRadius, 1);
  for (std::size_t slot = 0; slot < balls.size(); ++slot)
    cells.setCell(slot, cells.cellOf(balls[slot].x, balls[slot].y, balls[slot].radius,
                                     common::CellOrder::FromLowerLeft));
  cells.countShare(0);
  cells.sortShare(0, common::CellOrder::FromLowerLeft);
  return cells;
}

/// Every field of every ball, bit for bit (so NaN equals the same NaN).
void expectSameBits(const std::vector<Ball>& expected, const std::vector<Ball>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  const auto bits = [](double value) { return std::bit_cast<std::uint64_t>(value); };
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Ball& e = expected[i];
    const Ball& a = actual[i];
    ASSERT_TRUE(bits(e.x) == bits(a.x) && bits(e.y) == bits(a.y) && bits(e.vx) == bits(a.vx) &&
                bits(e.vy) == bits(a.vy) && bits(e.radius) == bits(a.radius) &&
                bits(e.mass) == bits(a.mass))
        << "ball " << i << ": scalar (" << e.x << ", " << e.y << ", " << e.vx << ", " << e.vy
        << "), this CPU's test (" << a.x << ", " << a.y << ", " << a.vx << ", " << a.vy << ")";
  }
}

/// The balls after one search of `balls` with the scalar lane test and with the one this CPU
/// runs (fastestLaneTest), and the impulses each exchanged.
struct Searched {
  std::vector<Ball> scalar;
  std::vector<Ball> fastest;
  std::uint64_t scalarImpulses = 0;
  std::uint64_t fastestImpulses = 0;
};

Searched searchWithBoth(const std::vector<Ball>& balls) {
  Searched searched{balls, balls};
  const common::CellLists cells = cellsFor(balls);
  NeighbourSlots scratch;
  searched.scalarImpulses =
      collideRows(searched.scalar, cells, 0, cells.rows(), scratch, LaneTest::Scalar);
  searched.fastestImpulses =
      collideRows(searched.fastest, cells, 0, cells.rows(), scratch, fastestLaneTest());
  return searched;
}

/// The searches below compare the AVX2 test with the scalar one wherever the CPU has AVX2 (this
/// project's machines and CI do); elsewhere the scalar test is all there is.
TEST(ElasticLaneTest, TheCpuGetsTheAvx2TestExactlyWhenItHasAvx2) {
  __builtin_cpu_init();
  EXPECT_EQ(fastestLaneTest(), __builtin_cpu_supports("avx2") ? LaneTest::Avx2 : LaneTest::Scalar);
}

TEST(ElasticLaneTest, TheCpusLaneTestResolvesTheSamePairsAsScalarBitForBit) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::vector<Ball> balls = denseBalls(seed, false);
    // Three searches, each on a grid rebuilt from where the last one left the balls.
    for (int search = 0; search < 3; ++search) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << ", search " << search);
      const Searched searched = searchWithBoth(balls);
      // Enough collisions that any lane tested wrongly changes some ball.
      EXPECT_GT(searched.scalarImpulses, 200u);
      EXPECT_EQ(searched.scalarImpulses, searched.fastestImpulses);
      expectSameBits(searched.scalar, searched.fastest);
      if (HasFatalFailure()) return;
      balls = searched.scalar;
    }
  }
}

/// A NaN centre counts as an overlap in both tests, so the NaN spreads to the balls the NaN ball
/// meets, and on from them, alike: a test that did not count it would leave them finite.
TEST(ElasticLaneTest, BothTestsCountANaNCentreAsAnOverlap) {
  const Searched searched = searchWithBoth(denseBalls(1, true));
  int nanBalls = 0;
  for (const Ball& ball : searched.scalar)
    nanBalls += std::isnan(ball.x) ? 1 : 0;
  EXPECT_GT(nanBalls, 1);
  EXPECT_EQ(searched.scalarImpulses, searched.fastestImpulses);
  expectSameBits(searched.scalar, searched.fastest);
}

}  // namespace
}  // namespace fooball::elastic
