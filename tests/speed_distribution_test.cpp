#include "fooball/speed_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

namespace fooball {
namespace {

/// Velocities drawn from the 2D Maxwell–Boltzmann distribution: each component normal with
/// variance kT/m.
std::vector<Vec2> thermalVelocities(const std::vector<double>& masses, double kT,
                                    unsigned seed = 3) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  std::vector<Vec2> velocities;
  for (const double m : masses) {
    const double spread = std::sqrt(kT / m);
    velocities.push_back({spread * normal(random), spread * normal(random)});
  }
  return velocities;
}

TEST(SpeedDistribution, KineticTemperatureIsTheMeanKineticEnergyPerBall) {
  const std::vector<double> masses = {1.0, 2.0, 4.0};
  const std::vector<Vec2> velocities = {{3.0, 4.0}, {0.0, 1.0}, {-1.0, 0.0}};
  // ½·1·25 + ½·2·1 + ½·4·1 = 12.5 + 1 + 2 = 15.5 J over three balls.
  EXPECT_DOUBLE_EQ(kineticTemperature(masses, velocities), 15.5 / 3.0);
  EXPECT_EQ(kineticTemperature({}, {}), 0.0);
}

TEST(SpeedDistribution, HistogramCountsEveryBallOnce) {
  const std::vector<double> masses(10'000, 0.5);
  std::vector<Vec2> velocities = thermalVelocities(masses, 2.0);
  velocities.push_back({1e9, 0.0});                                       // far beyond the range
  velocities.push_back({std::numeric_limits<double>::quiet_NaN(), 0.0});  // never in a bin
  velocities.push_back({0.0, 0.0});                                       // the first bin
  const SpeedHistogram histogram = speedHistogram(velocities, 40, 10.0);
  ASSERT_EQ(histogram.counts.size(), 40u);
  EXPECT_DOUBLE_EQ(histogram.binWidth, 0.25);
  EXPECT_DOUBLE_EQ(histogram.range(), 10.0);
  const std::size_t inBins =
      std::accumulate(histogram.counts.begin(), histogram.counts.end(), std::size_t{0});
  EXPECT_EQ(inBins + histogram.above, velocities.size());
  EXPECT_GE(histogram.above, 2u);
  EXPECT_GE(histogram.counts[0], 1u);
  // Each count by hand.
  std::vector<std::size_t> expected(40, 0);
  for (const Vec2 v : velocities) {
    const double speed = length(v);
    if (speed < 10.0) ++expected[static_cast<std::size_t>(speed / 0.25)];
  }
  EXPECT_EQ(histogram.counts, expected);
}

TEST(SpeedDistribution, HistogramRejectsNoBinsAndABadRange) {
  EXPECT_THROW(speedHistogram({}, 0, 1.0), std::invalid_argument);
  EXPECT_THROW(speedHistogram({}, 10, 0.0), std::invalid_argument);
  EXPECT_THROW(speedHistogram({}, 10, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

TEST(SpeedDistribution, MaxwellBoltzmannIntegratesToOneForOneAndManyMasses) {
  std::vector<double> manyMasses;
  for (int i = 0; i < 5000; ++i)
    manyMasses.push_back(0.01 + 0.001 * i);  // 5000 distinct masses: pooled into 64 terms
  for (const std::vector<double>& masses : {std::vector<double>(100, 0.03), manyMasses}) {
    const MaxwellBoltzmann2D curve(masses, 1.5);
    // Simpson's rule far into the tail: the slowest-decaying term has m/kT ≥ 0.0067 s²/m².
    const double top = 200.0;  // m/s
    const int intervals = 20'000;
    const double h = top / intervals;
    double integral = curve.density(0.0) + curve.density(top);
    for (int k = 1; k < intervals; ++k)
      integral += (k % 2 == 1 ? 4.0 : 2.0) * curve.density(k * h);
    integral *= h / 3.0;
    EXPECT_NEAR(integral, 1.0, 1e-6) << curve.terms() << " terms";
    EXPECT_NEAR(curve.probabilityBelow(top), 1.0, 1e-12);
    EXPECT_EQ(curve.probabilityBelow(0.0), 0.0);
    EXPECT_EQ(curve.density(-1.0), 0.0);
  }
  EXPECT_EQ(MaxwellBoltzmann2D(std::vector<double>(100, 0.03), 1.5).terms(), 1u);
  EXPECT_EQ(MaxwellBoltzmann2D(manyMasses, 1.5).terms(), MaxwellBoltzmann2D::kMaxTerms);
}

TEST(SpeedDistribution, MaxwellBoltzmannOfOneMassIsRayleigh) {
  const double m = 0.2;   // kg
  const double kT = 0.7;  // J
  const MaxwellBoltzmann2D curve(std::vector<double>(7, m), kT);
  for (const double v : {0.1, 1.0, 1.87, 3.0, 8.0}) {
    EXPECT_NEAR(curve.density(v), m * v / kT * std::exp(-m * v * v / (2.0 * kT)), 1e-15);
    EXPECT_NEAR(curve.probabilityBelow(v), 1.0 - std::exp(-m * v * v / (2.0 * kT)), 1e-15);
  }
  // The most probable speed of Rayleigh is √(kT/m).
  const double peak = std::sqrt(kT / m);
  EXPECT_GT(curve.density(peak), curve.density(peak * 0.99));
  EXPECT_GT(curve.density(peak), curve.density(peak * 1.01));
  EXPECT_NEAR(curve.expectedCount(0.0, peak, 1000), 1000.0 * (1.0 - std::exp(-0.5)), 1e-9);
}

TEST(SpeedDistribution, MaxwellBoltzmannRejectsWhatHasNoTemperatureOrMass) {
  EXPECT_THROW(MaxwellBoltzmann2D({}, 1.0), std::invalid_argument);
  EXPECT_THROW(MaxwellBoltzmann2D(std::vector<double>{1.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(MaxwellBoltzmann2D(std::vector<double>{1.0, -1.0}, 1.0), std::invalid_argument);
}

TEST(SpeedDistribution, ThermalSpeedsOfMixedMassesAreCloseToMaxwellBoltzmann) {
  std::vector<double> masses;
  for (int i = 0; i < 20'000; ++i)
    masses.push_back(i % 2 == 0 ? 0.01 : 1.0);  // two species, a hundred times apart
  const std::vector<Vec2> velocities = thermalVelocities(masses, 0.8);
  std::vector<double> scratch;
  const double kT = kineticTemperature(masses, velocities);
  EXPECT_NEAR(kT, 0.8, 0.8 * 0.03);
  // KS at α = 10⁻³ rejects beyond 1.95/√N = 0.0138.
  EXPECT_LT(maxwellBoltzmannDistance(masses, velocities, kT, scratch), 0.0138);

  // The same speeds all at one speed are far from it; so are the heavy balls' speeds given to
  // the light ones (kT then is the heavy balls').
  std::vector<Vec2> oneSpeed(masses.size(), Vec2{std::sqrt(2.0 * 0.8), 0.0});
  std::vector<double> oneMass(masses.size(), 1.0);
  EXPECT_GT(
      maxwellBoltzmannDistance(oneMass, oneSpeed, kineticTemperature(oneMass, oneSpeed), scratch),
      0.3);
  const std::vector<Vec2> heavySpeeds = thermalVelocities(oneMass, 0.8);
  EXPECT_GT(maxwellBoltzmannDistance(masses, heavySpeeds, 0.8, scratch), 0.3);
  EXPECT_EQ(maxwellBoltzmannDistance({}, {}, 1.0, scratch), 0.0);
}

}  // namespace
}  // namespace fooball
