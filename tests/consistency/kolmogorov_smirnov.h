#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fooball::testing {

/// Kolmogorov–Smirnov distance between the empirical distribution of `samples` (sorted in
/// place) and the distribution function `cdf`: the largest gap between the two.
template <class Cdf>
double ksDistance(std::vector<double>& samples, Cdf cdf) {
  std::sort(samples.begin(), samples.end());
  const double n = static_cast<double>(samples.size());
  double distance = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double f = cdf(samples[i]);
    distance =
        std::max({distance, static_cast<double>(i + 1) / n - f, f - static_cast<double>(i) / n});
  }
  return distance;
}

/// The largest gap between the empirical distributions of two samples (sorted in place).
inline double ksDistance(std::vector<double>& a, std::vector<double>& b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  std::size_t i = 0;
  std::size_t j = 0;
  double distance = 0.0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x)
      ++i;
    while (j < b.size() && b[j] <= x)
      ++j;
    distance =
        std::max(distance, std::abs(static_cast<double>(i) / na - static_cast<double>(j) / nb));
  }
  return distance;
}

/// The distance the KS test rejects at significance `alpha` for samples of `n` and `m`
/// independent draws (m = 0: one sample against a given distribution), from the asymptotic
/// Kolmogorov distribution: c(α)·√((n + m)/(n·m)) with c(α) = √(−½ ln(α/2)); accurate for the
/// thousands of draws used here.
inline double ksCriticalDistance(double alpha, double n, double m = 0.0) {
  const double c = std::sqrt(-0.5 * std::log(alpha / 2.0));
  return m > 0.0 ? c * std::sqrt((n + m) / (n * m)) : c / std::sqrt(n);
}

}  // namespace fooball::testing
