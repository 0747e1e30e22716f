#include "barrier_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "free_flight.h"

namespace fooball::exact {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

struct GapState {
  double gap;   ///< m
  double rate;  ///< m/s
};

class DraggedGap {
 public:
  DraggedGap(double gap, double rate, double acceleration, double drag)
      : gap_(gap), rate_(rate), acceleration_(acceleration), drag_(drag) {}

  GapState at(double tau) const {
    const FlightFactors f = dragFlightFactors(drag_, tau);
    return {gap_ + rate_ * f.s + acceleration_ * f.q, rate_ * f.decay + acceleration_ * f.s};
  }

  /// Where the rate passes through zero: rate·e^{−cτ} + (a/c)(1 − e^{−cτ}) = 0.
  double stationaryTime() const { return std::log1p(-drag_ * rate_ / acceleration_) / drag_; }

  /// A time at which the gap is surely ≤ 0 when it falls for ever (acceleration < 0): the gap
  /// is gap + (rate − a/c)·s + (a/c)·τ with s < 1/c, so the line gap + max(rate − a/c, 0)/c +
  /// (a/c)·τ lies above it.
  double fallenBelowTime() const {
    const double terminalRate = acceleration_ / drag_;
    return (gap_ + std::max(rate_ - terminalRate, 0.0) / drag_) / -terminalRate;
  }

  /// The root in [low, high], where the gap falls from > 0 to ≤ 0 monotonically: Newton steps
  /// kept inside the shrinking bracket, bisection when a step would leave it.
  double descendingRoot(double low, double high) const {
    for (int widen = 0; widen < 8 && at(high).gap > 0.0; ++widen)
      high *= 2.0;
    double tau = high;
    for (int iteration = 0; iteration < 200; ++iteration) {
      const GapState state = at(tau);
      if (state.gap > 0.0) {
        low = tau;
      } else {
        high = tau;
      }
      if (state.gap == 0.0 || high - low <= 4.0 * kEpsilon * high) return tau;
      const double newton = tau - state.gap / state.rate;
      const bool newtonInside = state.rate < 0.0 && newton > low && newton < high;
      const double next = newtonInside ? newton : 0.5 * (low + high);
      if (std::abs(next - tau) <= 4.0 * kEpsilon * tau) return next;
      tau = next;
    }
    return low;
  }

 private:
  double gap_;
  double rate_;
  double acceleration_;
  double drag_;
};

}  // namespace

double draggedBarrierContact(double gap, double rate, double acceleration, double drag) {
  if (acceleration == 0.0) {  // linear in s
    if (gap <= 0.0) return rate < 0.0 ? 0.0 : kNever;
    if (rate >= 0.0) return kNever;
    return timeForFlightParameter(drag, gap / -rate);
  }
  const DraggedGap flight(gap, rate, acceleration, drag);
  if (gap <= 0.0) {
    if (rate < 0.0 || (rate == 0.0 && acceleration < 0.0)) return 0.0;
    if (acceleration > 0.0) return kNever;
    const double apex = flight.stationaryTime();
    if (flight.at(apex).gap <= 0.0) return apex;  // turns back while still beyond
    return flight.descendingRoot(apex, flight.fallenBelowTime());
  }
  if (acceleration > 0.0) {  // convex: falls only while rate < 0, to a minimum
    if (rate >= 0.0) return kNever;
    const double lowest = flight.stationaryTime();
    if (flight.at(lowest).gap > 0.0) return kNever;
    return flight.descendingRoot(0.0, lowest);
  }
  const double start = rate > 0.0 ? flight.stationaryTime() : 0.0;
  return flight.descendingRoot(start, flight.fallenBelowTime());
}

}  // namespace fooball::exact
