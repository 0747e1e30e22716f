#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fooball/vec2.h"

namespace fooball {

/// Kinetic temperature kT (J): the mean kinetic energy per ball, ⟨½ m v²⟩. A ball in the plane
/// has two degrees of freedom, each holding ½ kT at equilibrium. 0 for no balls.
double kineticTemperature(std::span<const double> masses, std::span<const Vec2> velocities);

/// Ball speeds counted in `counts.size()` equal bins over [0, range): bin k holds the speeds in
/// [k·binWidth, (k+1)·binWidth). Speeds at or beyond the range are counted in `above`, so the
/// counts and `above` always add up to the number of balls.
struct SpeedHistogram {
  double binWidth = 0.0;            ///< m/s
  std::vector<std::size_t> counts;  ///< balls per bin
  std::size_t above = 0;            ///< balls at range or faster

  double range() const { return binWidth * static_cast<double>(counts.size()); }  ///< m/s
};

/// `bins` ≥ 1 and `range` > 0 (m/s), else std::invalid_argument.
SpeedHistogram speedHistogram(std::span<const Vec2> velocities, std::size_t bins, double range);

/// The 2D Maxwell–Boltzmann distribution of the speed of a ball picked at random from balls of
/// the given masses at temperature kT: each ball's speed is Rayleigh-distributed,
/// f(v) = (m v / kT) e^{−m v² / 2kT}, so the whole gas follows the mass-weighted mixture. Balls
/// of equal mass are one term; beyond kMaxTerms distinct masses, balls are pooled by mass into
/// kMaxTerms groups of equal count, each with its mean mass, so a curve costs the same for
/// 10⁶ balls as for 10⁴ (the pooled curve still integrates to 1).
class MaxwellBoltzmann2D {
 public:
  static constexpr std::size_t kMaxTerms = 64;

  /// `kT` > 0 (J) and at least one mass, every mass > 0, else std::invalid_argument.
  MaxwellBoltzmann2D(std::span<const double> masses, double kT);

  double density(double speed) const;           ///< 1/(m/s), the probability density at `speed`
  double probabilityBelow(double speed) const;  ///< the distribution function F(speed)
  /// The expected number of `balls` balls in [low, high) (m/s): balls·(F(high) − F(low)).
  double expectedCount(double low, double high, std::size_t balls) const;
  std::size_t terms() const { return terms_.size(); }

 private:
  struct Term {
    double weight;      ///< the share of balls, Σ = 1
    double massOverKT;  ///< s²/m², m / kT
  };
  std::vector<Term> terms_;
};

/// The Kolmogorov–Smirnov distance between the balls' speeds and the Maxwell–Boltzmann
/// distribution at temperature kT: the largest gap between the empirical and the theoretical
/// distribution function. Each speed is scaled to u = v·√(m/kT), which is Rayleigh(1)-distributed
/// at equilibrium whatever the ball's mass, so this is exact for mixed masses too and costs one
/// sort, O(N log N). `scratch` holds the scaled speeds (resized, reused). 0 for no balls; 1
/// when kT is 0 and some ball moves.
double maxwellBoltzmannDistance(std::span<const double> masses, std::span<const Vec2> velocities,
                                double kT, std::vector<double>& scratch);

}  // namespace fooball
