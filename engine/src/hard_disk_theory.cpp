#include "fooball/hard_disk_theory.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <numeric>
#include <vector>

namespace fooball {
namespace {

/// Balls pooled by radius into groups of equal count: the collision-rate sum is over groups, so
/// it costs the same for 10⁶ balls as for 10⁴.
constexpr std::size_t kSizeGroups = 16;

struct SizeGroup {
  double share = 0.0;   ///< of all balls
  double radius = 0.0;  ///< m, mean
  double mass = 0.0;    ///< kg, mean
};

std::vector<SizeGroup> sizeGroups(std::span<const double> radii, std::span<const double> masses) {
  std::vector<std::size_t> order(radii.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return radii[a] < radii[b] || (radii[a] == radii[b] && masses[a] < masses[b]);
  });
  const std::size_t count = std::min(kSizeGroups, order.size());
  std::vector<SizeGroup> groups;
  for (std::size_t g = 0; g < count; ++g) {
    const std::size_t begin = order.size() * g / count;
    const std::size_t end = order.size() * (g + 1) / count;
    SizeGroup group;
    for (std::size_t k = begin; k < end; ++k) {
      group.radius += radii[order[k]];
      group.mass += masses[order[k]];
    }
    const double balls = static_cast<double>(end - begin);
    group.share = balls / static_cast<double>(order.size());
    group.radius /= balls;
    group.mass /= balls;
    groups.push_back(group);
  }
  return groups;
}

}  // namespace

double hendersonCompressibility(double packingFraction) {
  const double eta = packingFraction;
  return (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
}

double hendersonContactValue(double packingFraction) {
  const double eta = packingFraction;
  return (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
}

HardDiskTheory hardDiskTheory(std::span<const double> radii, std::span<const double> masses,
                              const Box& box, double kT) {
  HardDiskTheory theory;
  if (radii.empty()) return theory;
  const double area = box.width * box.height;  // m²
  const double balls = static_cast<double>(radii.size());
  double diameterSum = 0.0;
  double diameterSquaredSum = 0.0;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    diameterSum += 2.0 * radii[i];
    diameterSquaredSum += 4.0 * radii[i] * radii[i];
    theory.equalSizes = theory.equalSizes && radii[i] == radii[0] && masses[i] == masses[0];
  }
  const double eta = std::numbers::pi * diameterSquaredSum / 4.0 / area;
  theory.packingFraction = eta;
  theory.numberDensity = balls / area;
  const double q = diameterSum * diameterSum / (balls * diameterSquaredSum);  // ⟨σ⟩²/⟨σ²⟩ ≤ 1
  theory.compressibility = (1.0 - q) / (1.0 - eta) + q * hendersonCompressibility(eta);
  if (!(kT > 0.0)) return theory;
  theory.pressure = theory.compressibility * theory.numberDensity * kT;

  const double contact = hendersonContactValue(eta);
  const std::vector<SizeGroup> groups = sizeGroups(radii, masses);
  for (const SizeGroup& a : groups) {
    double rate = 0.0;  // 1/s, of one ball of group a
    for (const SizeGroup& b : groups) {
      const double contactDistance = a.radius + b.radius;              // m
      const double reducedMass = a.mass * b.mass / (a.mass + b.mass);  // kg
      const double meanRelativeSpeed = std::sqrt(std::numbers::pi * kT / (2.0 * reducedMass));
      rate += b.share * theory.numberDensity * 2.0 * contactDistance * meanRelativeSpeed;
    }
    theory.collisionRate += a.share * rate * contact;
  }
  return theory;
}

}  // namespace fooball
