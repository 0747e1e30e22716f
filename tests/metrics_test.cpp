// Metrics against hand-computed values. Sums of a handful of terms are exact up to a few
// roundings, so they are checked to 1e-12 relative; the grid overlap search must find the same
// maximum as brute force, which computes each pair's depth by the same formula, so that
// comparison is also at rounding.

#include "fooball/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "test_scenes.h"  // PrintTo(Vec2)

namespace fooball {
namespace {

using testing::kRounding;

TEST(Metrics, SumStateGivesHandComputedEnergyMomentumAndCentreOfMass) {
  const std::vector<Vec2> positions = {{1.0, 3.0}, {5.0, -1.0}};
  const std::vector<Vec2> velocities = {{3.0, 4.0}, {-2.0, 0.0}};
  const std::vector<double> masses = {2.0, 1.0};
  const StateSums sums = sumState(positions, velocities, masses, {0.0, -9.81});
  // KE = ½·2·25 + ½·1·4 = 27 J; PE = Σ m·9.81·y = 2·9.81·3 − 9.81 = 49.05 J.
  EXPECT_NEAR(sums.kineticEnergy, 27.0, 27.0 * kRounding);
  EXPECT_NEAR(sums.potentialEnergy, 49.05, 49.05 * kRounding);
  EXPECT_NEAR(sums.totalEnergy(), 76.05, 76.05 * kRounding);
  EXPECT_NEAR(sums.momentum.x, 4.0, kRounding);  // 2·3 − 2
  EXPECT_NEAR(sums.momentum.y, 8.0, kRounding);  // 2·4
  EXPECT_NEAR(sums.centreOfMass.x, 7.0 / 3.0, kRounding);
  EXPECT_NEAR(sums.centreOfMass.y, 5.0 / 3.0, kRounding);

  // Sideways gravity: PE = −m g·p = −(2·2·1 + 1·2·5) = −14 J.
  const StateSums sideways = sumState(positions, velocities, masses, {2.0, 0.0});
  EXPECT_NEAR(sideways.potentialEnergy, -14.0, 14.0 * kRounding);
  EXPECT_EQ(sideways.kineticEnergy, sums.kineticEnergy);
}

TEST(Metrics, PotentialEnergyIsZeroAtTheFloorAndWithoutGravity) {
  const std::vector<Vec2> positions = {{3.0, 0.0}, {7.0, 0.0}};
  const std::vector<Vec2> velocities = {{0.0, 0.0}, {0.0, 0.0}};
  const std::vector<double> masses = {1.5, 4.0};
  EXPECT_EQ(sumState(positions, velocities, masses, {0.0, -9.81}).potentialEnergy, 0.0);
  const std::vector<Vec2> raised = {{3.0, 2.0}, {7.0, 5.0}};
  EXPECT_EQ(sumState(raised, velocities, masses, {0.0, 0.0}).potentialEnergy, 0.0);
  EXPECT_GT(sumState(raised, velocities, masses, {0.0, -9.81}).potentialEnergy, 0.0)
      << "higher is more potential energy under downward gravity";
}

TEST(Metrics, RelativeEnergyErrorIsTheResidualOverTheMagnitudeOfTheInitialEnergy) {
  EXPECT_EQ(relativeEnergyError(-0.5, 8.0), -0.0625);
  EXPECT_EQ(relativeEnergyError(0.25, -2.0), 0.125) << "|E(0)|: the sign is the residual's";
  EXPECT_EQ(relativeEnergyError(0.0, 3.0), 0.0);
  EXPECT_DOUBLE_EQ(relativeEnergyError(1e-30, 1e-20), 1e-10) << "no floor: a tiny E(0) is honest";
  EXPECT_TRUE(std::isnan(relativeEnergyError(1.0, 0.0))) << "nothing to be relative to";
  EXPECT_TRUE(std::isnan(relativeEnergyError(1.0, std::numeric_limits<double>::infinity())));
  Metrics metrics;
  metrics.energyResidual = 3.0;
  metrics.initialEnergy = -12.0;
  EXPECT_EQ(relativeEnergyError(metrics), 0.25);
}

TEST(Metrics, SumStateOfNoBallsIsZero) {
  const StateSums sums = sumState({}, {}, {}, {0.0, -9.81});
  EXPECT_EQ(sums.kineticEnergy, 0.0);
  EXPECT_EQ(sums.potentialEnergy, 0.0);
  EXPECT_EQ(sums.momentum, Vec2{});
  EXPECT_EQ(sums.centreOfMass, Vec2{});
}

const Box kBox{16.0, 9.0};
const Walls kAllWalls{};
const Walls kNoWalls{false, false, false, false};

TEST(Metrics, BallOverlapIsAFractionOfTheSmallerRadius) {
  // Radii 0.5 and 0.25, centres 0.65 m apart: 0.1 m deep, 0.4 of the smaller radius.
  const std::vector<Vec2> positions = {{5.0, 4.0}, {5.65, 4.0}};
  const std::vector<double> radii = {0.5, 0.25};
  EXPECT_NEAR(maxOverlap(positions, radii, kBox, kAllWalls), 0.4, kRounding);
  EXPECT_NEAR(maxOverlap(positions, radii, kBox, kNoWalls), 0.4, kRounding);

  // The deepest pair wins, wherever it is.
  const std::vector<Vec2> three = {{5.0, 4.0}, {5.65, 4.0}, {12.0, 2.0}, {12.0, 2.2}};
  const std::vector<double> threeRadii = {0.5, 0.25, 0.2, 0.2};
  EXPECT_NEAR(maxOverlap(three, threeRadii, kBox, kAllWalls), 1.0, kRounding);  // 0.2/0.2

  // Coincident centres: depth r₁ + r₂ over the smaller radius.
  const std::vector<Vec2> coincident = {{8.0, 4.0}, {8.0, 4.0}};
  EXPECT_NEAR(maxOverlap(coincident, radii, kBox, kAllWalls), 3.0, kRounding);
}

TEST(Metrics, NoOverlapWhenApartOrJustTouching) {
  const std::vector<double> radii = {0.5, 0.25};
  EXPECT_EQ(maxOverlap(std::vector<Vec2>{{5.0, 4.0}, {7.0, 4.0}}, radii, kBox, kAllWalls), 0.0);
  EXPECT_EQ(maxOverlap(std::vector<Vec2>{{5.0, 4.0}, {5.75, 4.0}}, radii, kBox, kAllWalls), 0.0);
  EXPECT_EQ(maxOverlap(std::vector<Vec2>{{0.5, 0.5}}, std::vector<double>{0.5}, kBox, kAllWalls),
            0.0)
      << "a ball resting in a corner touches two walls";
  EXPECT_EQ(maxOverlap({}, {}, kBox, kAllWalls), 0.0);
}

TEST(Metrics, WallOverlapCountsOnlyWallsThatAreOn) {
  const std::vector<double> radius = {0.5};
  struct Case {
    const char* wall;
    Vec2 position;
    Walls onlyThisWall;
  };
  // Each ball is 0.1 m into one wall: 0.2 of its radius.
  const Case cases[] = {
      {"left", {0.4, 4.5}, {true, false, false, false}},
      {"right", {15.6, 4.5}, {false, true, false, false}},
      {"bottom", {8.0, 0.4}, {false, false, true, false}},
      {"top", {8.0, 8.6}, {false, false, false, true}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.wall);
    const std::vector<Vec2> position = {c.position};
    EXPECT_NEAR(maxOverlap(position, radius, kBox, kAllWalls), 0.2, kRounding);
    EXPECT_NEAR(maxOverlap(position, radius, kBox, c.onlyThisWall), 0.2, kRounding);
    EXPECT_EQ(maxOverlap(position, radius, kBox, kNoWalls), 0.0);
    Walls allButThis = c.onlyThisWall;
    allButThis.left = !allButThis.left;
    allButThis.right = !allButThis.right;
    allButThis.bottom = !allButThis.bottom;
    allButThis.top = !allButThis.top;
    EXPECT_EQ(maxOverlap(position, radius, kBox, allButThis), 0.0);
  }
  // A ball whose centre is 1 m past the left wall: 1.5 m deep, 3 radii.
  EXPECT_NEAR(maxOverlap(std::vector<Vec2>{{-1.0, 4.5}}, radius, kBox, kAllWalls), 3.0, kRounding);
}

/// The definition, over all pairs.
double bruteForceMaxOverlap(const std::vector<Vec2>& positions, const std::vector<double>& radii,
                            const Box& box, const Walls& walls) {
  double deepest = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 p = positions[i];
    const double r = radii[i];
    if (walls.left) deepest = std::max(deepest, (r - p.x) / r);
    if (walls.right) deepest = std::max(deepest, (p.x + r - box.width) / r);
    if (walls.bottom) deepest = std::max(deepest, (r - p.y) / r);
    if (walls.top) deepest = std::max(deepest, (p.y + r - box.height) / r);
    for (std::size_t j = i + 1; j < positions.size(); ++j) {
      const double reach = radii[i] + radii[j];
      const double distanceSquared = lengthSquared(positions[i] - positions[j]);
      if (distanceSquared >= reach * reach) continue;
      const double depth = reach - std::sqrt(distanceSquared);
      deepest = std::max(deepest, depth / std::min(radii[i], radii[j]));
    }
  }
  return deepest;
}

TEST(Metrics, MaxOverlapAgreesWithBruteForceOnTwoThousandRandomBalls) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> x(0.0, kBox.width);
    std::uniform_real_distribution<double> y(0.0, kBox.height);
    // Radii spread over a factor 10 (the grid's cells follow the largest): 2,000 balls cover
    // ~16% of the box, so many pairs overlap a little and a few a lot.
    std::uniform_real_distribution<double> radius(0.01, 0.1);
    std::vector<Vec2> positions(2000);
    std::vector<double> radii(2000);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] = {x(random), y(random)};
      radii[i] = radius(random);
    }
    // Two large balls overlapping near the top right corner (a bigger largest radius means
    // bigger cells), and one ball far outside the box for the grid's clamp.
    positions[0] = {15.0, 8.0};
    positions[1] = {15.0 + 0.1 * static_cast<double>(seed), 8.05};
    radii[0] = radii[1] = 0.2;
    positions[2] = {40.0, -30.0};

    const Walls wallsOff = kNoWalls;
    const double expectedNoWalls = bruteForceMaxOverlap(positions, radii, kBox, wallsOff);
    EXPECT_GT(expectedNoWalls, 0.0);
    EXPECT_NEAR(maxOverlap(positions, radii, kBox, wallsOff), expectedNoWalls,
                kRounding * expectedNoWalls);

    positions[2] = {kBox.width - 0.5 * radii[2], 4.0};  // half a radius into the right wall
    const double expectedWalls = bruteForceMaxOverlap(positions, radii, kBox, kAllWalls);
    EXPECT_NEAR(maxOverlap(positions, radii, kBox, kAllWalls), expectedWalls,
                kRounding * expectedWalls);
  }
}

TEST(Metrics, MaxOverlapAgreesWithBruteForceOnADenseGasOfTwoSizes) {
  // 3,000 balls crowded into 2 m × 2 m (~25 % packing) with radii from 0.01 to 0.02 m, so they
  // fall into two power-of-two grids that span fewer cells than a few per ball: the search
  // sorts them by counting cells rather than comparing, and must still see every pair.
  for (const std::uint64_t seed : {4u, 5u}) {
    SCOPED_TRACE(seed);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(3.0, 5.0);
    std::uniform_real_distribution<double> radius(0.01, 0.02);
    std::vector<Vec2> positions(3000);
    std::vector<double> radii(3000);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] = {coordinate(random), coordinate(random)};
      radii[i] = radius(random);
    }
    const double expected = bruteForceMaxOverlap(positions, radii, kBox, kNoWalls);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(maxOverlap(positions, radii, kBox, kNoWalls), expected, kRounding * expected);
  }
}

TEST(Metrics, MaxOverlapFindsAShallowOverlapOfTheLargestBallsAnywhere) {
  // The hardest pair for a grid: the two largest balls, barely overlapping (centres 1.9 radii
  // apart), among many small balls that make the grid fine. Slid across the box in steps
  // smaller than a cell, the pair straddles every kind of cell boundary.
  std::vector<Vec2> positions;
  std::vector<double> radii;
  for (int row = 0; row < 10; ++row) {
    for (int column = 0; column < 200; ++column) {
      positions.push_back({0.04 + 0.08 * column, 0.04 + 0.08 * row});  // touching, no overlap
      radii.push_back(0.04);
    }
  }
  const double radius = 0.5;
  positions.push_back({});
  positions.push_back({});
  radii.push_back(radius);
  radii.push_back(radius);
  const std::size_t a = positions.size() - 2;
  const std::size_t b = positions.size() - 1;
  for (int k = 0; k < 40; ++k) {
    SCOPED_TRACE(k);
    const double x = 2.0 + 0.173 * k;
    const double y = 3.0 + 0.071 * k;
    const Vec2 direction = k % 2 == 0 ? Vec2{1.0, 0.0} : Vec2{0.6, 0.8};
    positions[a] = {x, y};
    positions[b] = positions[a] + 1.9 * radius * direction;
    EXPECT_NEAR(maxOverlap(positions, radii, kBox, kAllWalls), 0.1, 1e-12);
  }
}

TEST(Metrics, MaxOverlapFindsASmallBallSunkIntoABigOneAmongManySmallOnes) {
  // Touching small balls (r 0.04 m) on a lattice, with holes cleared for three big ones (r 0.5
  // m); one small ball sinks 0.01 m into a big one, a quarter of its radius. A grid sized for
  // the big balls would hold dozens of small ones per cell; one sized for the small ones would
  // miss the pair. Slid across the box, the big ball straddles every kind of cell boundary.
  constexpr double kSmall = 0.04;
  constexpr double kBig = 0.5;
  for (int k = 0; k < 30; ++k) {
    SCOPED_TRACE(k);
    const std::vector<Vec2> bigCentres = {
        {2.0 + 0.173 * k, 3.0 + 0.071 * k}, {12.0, 2.0}, {8.0, 7.0 - 0.05 * k}};
    std::vector<Vec2> positions;
    std::vector<double> radii;
    for (int row = 0; row * 2.0 * kSmall < kBox.height - kSmall; ++row) {
      for (int column = 0; column * 2.0 * kSmall < kBox.width - kSmall; ++column) {
        const Vec2 p{kSmall + 2.0 * kSmall * column, kSmall + 2.0 * kSmall * row};
        // Clear of the big ball and of the small ball sunk into it (0.53 m from its centre).
        const auto clear = [&](Vec2 c) { return length(p - c) > kBig + 4.0 * kSmall; };
        if (std::all_of(bigCentres.begin(), bigCentres.end(), clear)) {
          positions.push_back(p);
          radii.push_back(kSmall);
        }
      }
    }
    for (const Vec2 centre : bigCentres) {
      positions.push_back(centre);
      radii.push_back(kBig);
    }
    const double angle = 0.37 * k;
    positions.push_back(bigCentres[0] +
                        (kBig + kSmall - 0.01) * Vec2{std::cos(angle), std::sin(angle)});
    radii.push_back(kSmall);
    ASSERT_GT(positions.size(), 15'000u);
    // The lattice's touching pairs overlap by rounding at most (1e-16 m of 0.04 m).
    EXPECT_NEAR(maxOverlap(positions, radii, kBox, kNoWalls), 0.01 / kSmall, 1e-12);
  }
}

TEST(Metrics, CountEscapedCountsCentresOutsideTheBox) {
  const std::vector<Vec2> positions = {
      {8.0, 4.5},
      {0.0, 0.0},
      {16.0, 9.0},  // inside, and on the boundary (still inside)
      {-0.1, 4.5},
      {16.1, 4.5},
      {8.0, -0.1},
      {8.0, 9.1},                                       // one past each side
      {std::numeric_limits<double>::quiet_NaN(), 4.5},  // lost to NaN: not in the box either
  };
  EXPECT_EQ(countEscaped(positions, kBox), 5u);
  EXPECT_EQ(countEscaped(std::span(positions).first(3), kBox), 0u);
  EXPECT_EQ(countEscaped({}, kBox), 0u);
}

}  // namespace
}  // namespace fooball
