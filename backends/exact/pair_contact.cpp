#include "pair_contact.h"

#include <cmath>
#include <limits>

#include "free_flight.h"

namespace fooball::exact {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
/// Steps before giving up with a Recheck: near contacts converge in a handful; this only ends
/// searches along an unbounded horizon.
constexpr int kMaxSteps = 200;

struct SquaredGap {
  double value;  ///< m², |r|² − R²
  double rate;   ///< m²/s, its time derivative 2 r·r'
};

class CurvedPair {
 public:
  CurvedPair(const PairMotion& motion, double drag) : motion_(motion), drag_(drag) {
    speed_ = length(motion.relativeVelocity);
    acceleration_ = length(motion.relativeGravity);
    // r'' = (g_rel − c·u)·e^{−cτ}, so its size never exceeds |g_rel − c·u|.
    accelerationBound_ = length(motion.relativeGravity - drag * motion.relativeVelocity);
    distance_ = length(motion.separation);
  }

  SquaredGap at(double tau) const {
    const FlightFactors f = flightFactors(drag_, tau);
    const Vec2 r = motion_.separation +
                   flightDisplacement(motion_.relativeVelocity, motion_.relativeGravity, f);
    const Vec2 rDot = flightVelocity(motion_.relativeVelocity, motion_.relativeGravity, f);
    return {dot(r, r) - motion_.reach * motion_.reach, 2.0 * dot(r, rDot)};
  }

  /// A bound on |F''| over [0, end]: |r'| ≤ |u| + |g_rel|·τ and |r| ≤ |r0| + |u|·τ + ½|g_rel|τ²
  /// (since e^{−cτ} ≤ 1, s ≤ τ, q ≤ τ²/2).
  double curvatureBound(double end) const {
    const double speed = speed_ + acceleration_ * end;
    const double distance = distance_ + speed_ * end + 0.5 * acceleration_ * end * end;
    return 2.0 * (speed * speed + distance * accelerationBound_);
  }

 private:
  PairMotion motion_;
  double drag_;
  double speed_ = 0.0;
  double acceleration_ = 0.0;
  double accelerationBound_ = 0.0;
  double distance_ = 0.0;
};

/// The largest step from a state that cannot pass a contact, given |F''| ≤ bound.
double safeStep(const SquaredGap& gap, double bound) {
  if (gap.value > 0.0) {  // first root of F + F'Δ − ½MΔ²
    if (bound == 0.0) return gap.rate < 0.0 ? gap.value / -gap.rate : kNever;
    return (gap.rate + std::sqrt(gap.rate * gap.rate + 2.0 * bound * gap.value)) / bound;
  }
  // Overlapping by rounding and receding: F' cannot reach zero (start approaching) sooner.
  return bound == 0.0 ? kNever : gap.rate / bound;
}

}  // namespace

PairContact acceleratedPairContact(const PairMotion& motion, double drag, double horizon) {
  const CurvedPair pair(motion, drag);
  double tau = 0.0;
  SquaredGap gap = pair.at(tau);
  // Touching or overlapping and not moving apart: contact now (moving apart is left to the
  // stepping, which waits until the pair turns back or separates).
  if (gap.value <= 0.0 && gap.rate <= 0.0) return {PairContactKind::Contact, 0.0};
  double window = std::isfinite(horizon) ? horizon : 1.0;  // s, doubled while too short
  for (int stepIndex = 0; stepIndex < kMaxSteps; ++stepIndex) {
    if (tau >= horizon) return {PairContactKind::None, 0.0};
    const double step = safeStep(gap, pair.curvatureBound(tau + window));
    if (!(step <= window)) {
      tau += window;
      window *= 2.0;
    } else {
      if (step <= 4.0 * kEpsilon * tau) {
        return tau < horizon ? PairContact{PairContactKind::Contact, tau}
                             : PairContact{PairContactKind::None, 0.0};
      }
      tau += step;
      window = 2.0 * step;
    }
    gap = pair.at(tau);
    if (gap.value <= 0.0 && gap.rate <= 0.0) {
      return tau < horizon ? PairContact{PairContactKind::Contact, tau}
                           : PairContact{PairContactKind::None, 0.0};
    }
  }
  return {PairContactKind::Recheck, tau};
}

}  // namespace fooball::exact
