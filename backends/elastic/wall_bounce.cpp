#include "wall_bounce.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fooball::elastic {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

/// The first time t > 0 (s) at which d(t) = u t + ½ a t² reaches `span` (m), for u ≥ 0 (m/s)
/// and span ≥ 0, or kNever. The root formula without cancellation: t = 2·span / (u + √disc).
double timeToReach(double span, double u, double a) {
  const double disc = u * u + 2.0 * a * span;
  if (disc < 0.0) return kNever;  // turns back first
  const double denominator = u + std::sqrt(disc);
  return denominator > 0.0 ? 2.0 * span / denominator : kNever;
}

}  // namespace

void WallBounce::bounceAxis(double& p, double& v, double r, double mass, const Axis& axis,
                            common::WallTouches& touches, WallTally& tally) {
  const double span = axis.length - 2.0 * r;  // m the centre can travel between the walls
  const bool low = p < r;
  const bool crossedOn = low ? axis.lowOn : axis.highOn && p > axis.length - r;
  const common::WallBit crossed = low ? axis.lowWall : axis.highWall;
  const common::WallBit other = low ? axis.highWall : axis.lowWall;
  if (crossedOn && span >= 0.0) {
    // Seen from the crossed wall: depth D > 0 (m) past it, outward speed W (m/s) and inward
    // acceleration a (m/s²).
    const double depth = low ? r - p : p - (axis.length - r);
    const double outward = low ? -v : v;
    const double a = low ? axis.gravity : -axis.gravity;
    // A ball that flew there crossed the wall τ ago (W τ + ½ a τ² = D) moving out, which needs
    // W > 0, or a > 0 (it crossed and is turning back). Otherwise a ball pushed it in.
    if (outward <= 0.0 && a <= 0.0) {
      // Put back at contact, which lifts it by D against the gravity a ≤ 0: paid from its
      // inward speed as far as that goes, so the energy along the axis is kept if it can be.
      const double inward = std::sqrt(std::max(0.0, outward * outward + 2.0 * a * depth));
      p = low ? r : axis.length - r;
      v = low ? inward : -inward;
      // It did not fly into the wall, so no collision begins; but it touches the wall now.
      common::touchWall(touches, crossed);
    } else {
      // It crossed at speed u with ½u² = ½W² + aD (energy along the axis). Clamped at 0: for
      // rounding, or a ball pushed in deeper than its speed could carry it (a ball collision;
      // then the lift to the wall is not paid for).
      const double u = std::sqrt(std::max(0.0, outward * outward + 2.0 * a * depth));
      double tau = outward > 0.0 ? 2.0 * depth / (outward + u) : (u - outward) / a;  // s
      // Reflected there, its motion along the axis repeats: back at the same wall at speed u
      // after 2·t1 if it reaches the other wall at t1 (mirror-symmetric in time about t1), or
      // after 2u/|a| if gravity brings it back first. Many bounces fit in τ when u is small.
      const bool otherOn = low ? axis.highOn : axis.lowOn;
      const double toOther = otherOn ? timeToReach(span, u, a) : kNever;
      const double period = toOther < kNever ? 2.0 * toOther : (a < 0.0 ? 2.0 * u / -a : kNever);
      double periods = 0.0;  // whole periods in τ
      if (period == 0.0) {
        tau = 0.0;  // it just reaches the wall and rests there
      } else if (tau >= period) {
        periods = std::floor(tau / period);
        tau = std::fmod(tau, period);
      }
      const bool fromOther = tau > toOther;  // in the second half of a period
      if (fromOther) tau = period - tau;
      const double depthIn = std::clamp(u * tau + 0.5 * a * tau * tau, 0.0, span);  // m
      const double speedIn = (fromOther ? -1.0 : 1.0) * (u + a * tau);              // m/s
      p = low ? r + depthIn : axis.length - r - depthIn;
      v = low ? speedIn : -speedIn;
      // Σ|Δp|: 2u at this wall and 2(u + a·t1) at the other, per period and in the last one.
      // The count is capped so that a ball resting on a wall (u → 0) cannot overflow it.
      const double otherSpeed = toOther < kNever ? u + a * toOther : 0.0;
      const double perPeriod = 2.0 * (u + otherSpeed);
      tally.impulse +=
          mass * (periods * perPeriod + 2.0 * u + (fromOther ? 2.0 * otherSpeed : 0.0));
      // Whole periods between the two walls cross the box: each is two collisions. Periods of
      // a bounce under gravity shorter than a substep rise by g·h²/8 at most: a ball resting on
      // the wall, in the collision it began.
      const double crossings = toOther < kNever ? 2.0 * periods : 0.0;
      tally.bounces += static_cast<std::uint64_t>(std::min(crossings, 1e9));
      if (crossings > 0.0) touches = 0;
      tally.bounces += common::touchWall(touches, crossed);
      if (fromOther) tally.bounces += common::touchWall(touches, other);
    }
  }
  // Put back at contact after rounding, or a ball wider than the box.
  if (axis.lowOn) p = std::max(p, r);
  if (axis.highOn) p = std::min(p, axis.length - r);
}

}  // namespace fooball::elastic
