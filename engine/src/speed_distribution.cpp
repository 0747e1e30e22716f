#include "fooball/speed_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fooball {

double kineticTemperature(std::span<const double> masses, std::span<const Vec2> velocities) {
  if (masses.empty()) return 0.0;
  double energy = 0.0;  // J
  for (std::size_t i = 0; i < masses.size(); ++i)
    energy += 0.5 * masses[i] * lengthSquared(velocities[i]);
  return energy / static_cast<double>(masses.size());
}

SpeedHistogram speedHistogram(std::span<const Vec2> velocities, std::size_t bins, double range) {
  if (bins < 1) throw std::invalid_argument("speed histogram: needs at least one bin");
  if (!(range > 0.0) || !std::isfinite(range))
    throw std::invalid_argument("speed histogram: the range must be a positive speed");
  SpeedHistogram histogram;
  histogram.binWidth = range / static_cast<double>(bins);
  histogram.counts.assign(bins, 0);
  for (const Vec2 v : velocities) {
    const double bin = length(v) / histogram.binWidth;  // NaN and inf count as above the range
    if (bin >= 0.0 && bin < static_cast<double>(bins))
      ++histogram.counts[static_cast<std::size_t>(bin)];
    else
      ++histogram.above;
  }
  return histogram;
}

MaxwellBoltzmann2D::MaxwellBoltzmann2D(std::span<const double> masses, double kT) {
  if (!(kT > 0.0) || !std::isfinite(kT))
    throw std::invalid_argument("Maxwell-Boltzmann: the temperature kT must be > 0 J");
  if (masses.empty()) throw std::invalid_argument("Maxwell-Boltzmann: needs at least one ball");
  std::vector<double> sorted(masses.begin(), masses.end());
  std::sort(sorted.begin(), sorted.end());
  if (!(sorted.front() > 0.0) || !std::isfinite(sorted.back()))
    throw std::invalid_argument("Maxwell-Boltzmann: every mass must be > 0 kg");
  const double balls = static_cast<double>(sorted.size());
  // Runs of equal masses are one term each; with more runs than kMaxTerms, equal-count groups.
  std::vector<std::pair<std::size_t, std::size_t>> groups;  // [begin, end) in `sorted`
  for (std::size_t begin = 0; begin < sorted.size();) {
    std::size_t end = begin + 1;
    while (end < sorted.size() && sorted[end] == sorted[begin])
      ++end;
    groups.emplace_back(begin, end);
    begin = end;
  }
  if (groups.size() > kMaxTerms) {
    groups.clear();
    for (std::size_t g = 0; g < kMaxTerms; ++g)
      groups.emplace_back(sorted.size() * g / kMaxTerms, sorted.size() * (g + 1) / kMaxTerms);
  }
  for (const auto& [begin, end] : groups) {
    double sum = 0.0;
    for (std::size_t i = begin; i < end; ++i)
      sum += sorted[i];
    const double count = static_cast<double>(end - begin);
    terms_.push_back({count / balls, sum / count / kT});
  }
}

double MaxwellBoltzmann2D::density(double speed) const {
  if (!(speed > 0.0)) return 0.0;
  double f = 0.0;
  for (const Term& term : terms_)
    f += term.weight * term.massOverKT * speed * std::exp(-0.5 * term.massOverKT * speed * speed);
  return f;
}

double MaxwellBoltzmann2D::probabilityBelow(double speed) const {
  if (!(speed > 0.0)) return 0.0;
  double below = 0.0;
  for (const Term& term : terms_)
    below -= term.weight * std::expm1(-0.5 * term.massOverKT * speed * speed);
  return below;
}

double MaxwellBoltzmann2D::expectedCount(double low, double high, std::size_t balls) const {
  return static_cast<double>(balls) * (probabilityBelow(high) - probabilityBelow(low));
}

double maxwellBoltzmannDistance(std::span<const double> masses, std::span<const Vec2> velocities,
                                double kT, std::vector<double>& scratch) {
  if (masses.empty()) return 0.0;
  if (!(kT > 0.0)) return kineticTemperature(masses, velocities) > 0.0 ? 1.0 : 0.0;
  scratch.resize(masses.size());
  for (std::size_t i = 0; i < masses.size(); ++i)
    scratch[i] = length(velocities[i]) * std::sqrt(masses[i] / kT);
  std::sort(scratch.begin(), scratch.end());
  const double n = static_cast<double>(scratch.size());
  double distance = 0.0;
  for (std::size_t i = 0; i < scratch.size(); ++i) {
    const double below = -std::expm1(-0.5 * scratch[i] * scratch[i]);  // Rayleigh(1)
    distance = std::max(
        {distance, static_cast<double>(i + 1) / n - below, below - static_cast<double>(i) / n});
  }
  return distance;
}

}  // namespace fooball
