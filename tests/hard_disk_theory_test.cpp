#include "fooball/hard_disk_theory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "fooball/gas_window.h"

namespace fooball {
namespace {

TEST(HardDiskTheory, HendersonIsIdealAtZeroDensityAndMatchesItsContactValue) {
  EXPECT_DOUBLE_EQ(hendersonCompressibility(0.0), 1.0);
  for (const double eta : {0.05, 0.2, 0.3, 0.5, 0.65})
    EXPECT_NEAR(hendersonCompressibility(eta), 1.0 + 2.0 * eta * hendersonContactValue(eta), 1e-12);
  // Henderson's Z at η = 0.3, by hand: (1 + 0.09/8) / 0.49 = 2.06377.
  EXPECT_NEAR(hendersonCompressibility(0.3), 1.011250 / 0.49, 1e-12);
}

TEST(HardDiskTheory, EqualBallsGiveHendersonAndEnskog) {
  const double r = 0.1;  // m
  const double m = std::numbers::pi * r * r;
  const std::size_t n = 1375;
  const Box box{16.0, 9.0};
  const double kT = 0.4;  // J
  const HardDiskTheory theory =
      hardDiskTheory(std::vector<double>(n, r), std::vector<double>(n, m), box, kT);
  const double eta = n * std::numbers::pi * r * r / (16.0 * 9.0);
  EXPECT_TRUE(theory.equalSizes);
  EXPECT_NEAR(theory.packingFraction, eta, 1e-13);  // 1375 terms summed: rounding
  EXPECT_NEAR(theory.numberDensity, n / 144.0, 1e-15);
  EXPECT_NEAR(theory.compressibility, hendersonCompressibility(eta), 1e-12);
  EXPECT_NEAR(theory.pressure, hendersonCompressibility(eta) * n * kT / 144.0, 1e-12);
  // Enskog for one size: n · 2σ · √(π kT / m) · χ, σ = 2r.
  const double enskog = n / 144.0 * 2.0 * (2.0 * r) * std::sqrt(std::numbers::pi * kT / m) *
                        hendersonContactValue(eta);
  EXPECT_NEAR(theory.collisionRate, enskog, 1e-12 * enskog);
}

TEST(HardDiskTheory, MixedSizesKeepTheExactSecondVirialCoefficient) {
  // Z = 1 + B₂ n + O(n²), with B₂ = (π/4)(⟨σ²⟩ + ⟨σ⟩²) for an additive 2D mixture.
  std::vector<double> radii;
  std::vector<double> masses;
  for (int i = 0; i < 100; ++i) {
    radii.push_back(i % 2 == 0 ? 0.001 : 0.004);  // a dilute binary mixture
    masses.push_back(1.0);
  }
  const Box box{100.0, 100.0};
  const HardDiskTheory theory = hardDiskTheory(radii, masses, box, 1.0);
  EXPECT_FALSE(theory.equalSizes);
  const double meanSigma = (0.002 + 0.008) / 2.0;
  const double meanSigmaSquared = (0.002 * 0.002 + 0.008 * 0.008) / 2.0;
  const double b2 = std::numbers::pi / 4.0 * (meanSigmaSquared + meanSigma * meanSigma);
  const double n = theory.numberDensity;
  EXPECT_NEAR(theory.compressibility - 1.0, b2 * n, 1e-3 * b2 * n);
}

TEST(HardDiskTheory, NoBallsOrNoTemperatureGiveNoPressure) {
  EXPECT_EQ(hardDiskTheory({}, {}, Box{}, 1.0).pressure, 0.0);
  const HardDiskTheory cold =
      hardDiskTheory(std::vector<double>{0.5}, std::vector<double>{1.0}, Box{}, 0.0);
  EXPECT_EQ(cold.pressure, 0.0);
  EXPECT_EQ(cold.collisionRate, 0.0);
  EXPECT_GT(cold.packingFraction, 0.0);
}

TEST(GasWindow, RatesOverTheLastSeconds) {
  GasWindow window(2.0);
  EXPECT_EQ(window.span(), 0.0);
  EXPECT_EQ(window.wallPressure(Box{16.0, 9.0}, Walls{}), 0.0);
  // 3 N·s and 10 collisions per second, steadily.
  for (int k = 0; k <= 600; ++k) {
    const double t = k / 60.0;
    window.add(t, 3.0 * t, static_cast<std::uint64_t>(std::floor(10.0 * t)));
  }
  EXPECT_NEAR(window.span(), 2.0, 1.0 / 60.0);
  EXPECT_NEAR(window.wallPressure(Box{16.0, 9.0}, Walls{}), 3.0 / 50.0, 1e-9);
  EXPECT_NEAR(window.wallPressure(Box{16.0, 9.0}, Walls{false, false, true, true}), 3.0 / 32.0,
              1e-9);
  EXPECT_EQ(window.wallPressure(Box{16.0, 9.0}, Walls{false, false, false, false}), 0.0);
  EXPECT_NEAR(window.collisionRate(5), 2.0 * 10.0 / 5.0, 2.0 * 1.0 / (5.0 * 2.0));
  // A restart clears the window.
  window.add(0.0, 0.0, 0);
  EXPECT_EQ(window.span(), 0.0);
  EXPECT_THROW(GasWindow(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace fooball
