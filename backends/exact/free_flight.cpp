#include "free_flight.h"

#include <cmath>
#include <limits>

namespace fooball::exact {

namespace {

/// Below this c·τ, q = (τ − s)/c loses digits to cancellation (relative error ≈ 2ε/(cτ)), so the
/// Taylor series q = τ² Σ_k (−cτ)^k/(k+2)! is used; nine terms leave a truncation error below
/// (0.1)^9/11! ≈ 3e-17 of q.
constexpr double kSeriesLimit = 0.1;

double dragIntegralSeries(double tau, double x) {
  double sum = 1.0 / 3628800.0;  // 1/10!
  constexpr double kInverseFactorials[] = {1.0 / 362880.0, 1.0 / 40320.0, 1.0 / 5040.0, 1.0 / 720.0,
                                           1.0 / 120.0,    1.0 / 24.0,    1.0 / 6.0,    1.0 / 2.0};
  for (double coefficient : kInverseFactorials)
    sum = coefficient - x * sum;
  return tau * tau * sum;
}

}  // namespace

FlightFactors dragFlightFactors(double drag, double tau) {
  const double x = drag * tau;
  const double s = -std::expm1(-x) / drag;
  const double q = x < kSeriesLimit ? dragIntegralSeries(tau, x) : (tau - s) / drag;
  return {std::exp(-x), s, q};
}

double draggedFlightTime(double drag, double s) {
  const double x = drag * s;
  if (x >= 1.0) return std::numeric_limits<double>::infinity();
  return -std::log1p(-x) / drag;
}

}  // namespace fooball::exact
