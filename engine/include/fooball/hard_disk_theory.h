#pragma once

#include <span>

#include "fooball/scene.h"

namespace fooball {

/// What the theory of a hard-disk gas in equilibrium predicts for a set of balls in a box, to set
/// beside what a backend measures (the app's statistics dock, tests/consistency). Every formula
/// is exact in form for balls of one size; for mixed sizes it uses the closest simple theory,
/// named where it is used, and `equalSizes` says which case applies.
struct HardDiskTheory {
  double packingFraction = 0.0;  ///< η = Σ π r² / box area
  double numberDensity = 0.0;    ///< 1/m², N / box area
  double compressibility = 1.0;  ///< Z = P A / (N kT), 1 for an ideal gas
  double pressure = 0.0;         ///< N/m, the 2D pressure Z·N·kT/A (force per length of wall)
  double collisionRate = 0.0;    ///< ball–ball collisions per ball per second (Enskog)
  bool equalSizes = true;        ///< every ball has the same radius and mass
};

/// Henderson's equation of state for hard disks (Mol. Phys. 30, 971, 1975):
/// Z(η) = (1 + η²/8) / (1 − η)², accurate to about 1% up to η ≈ 0.6.
double hendersonCompressibility(double packingFraction);

/// Henderson's contact value of the pair correlation, χ(η) = (1 − 7η/16) / (1 − η)²: the
/// factor by which neighbours at contact are denser than on average. Z = 1 + 2ηχ.
double hendersonContactValue(double packingFraction);

/// The theory at temperature kT (J) for balls with these radii (m) and masses (kg) in `box`.
/// Pressure: Henderson for one size; for mixed sizes the Santos–Yuste–López de Haro mapping
/// (Mol. Phys. 96, 1, 1999) Z = (1 − q)/(1 − η) + q·Z_Henderson(η) with q = ⟨σ⟩²/⟨σ²⟩, which
/// keeps the exact second virial coefficient of the mixture. Collision rate: Enskog,
/// ν_i = Σ_j n_j · 2σ_ij · √(π kT / 2μ_ij) · χ(η), summed over up to 16 size groups with
/// σ_ij = r_i + r_j the contact distance, μ_ij the reduced mass and one contact value χ for all
/// pairs (exact for one size). No balls, or kT ≤ 0: zero pressure and rate.
HardDiskTheory hardDiskTheory(std::span<const double> radii, std::span<const double> masses,
                              const Box& box, double kT);

}  // namespace fooball
