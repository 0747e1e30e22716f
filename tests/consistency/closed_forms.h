#pragma once

#include <cmath>
#include <utility>

#include "fooball/scene.h"
#include "fooball/vec2.h"

namespace fooball::testing {

/// A ball's centre (m) and velocity (m/s) at one time.
struct Motion {
  Vec2 position;
  Vec2 velocity;
};

/// Two balls in free flight that meet once: the contact and both motions `seconds` after the
/// start, from straight lines and the elastic impulse along the line of centres.
struct TwoBallCollision {
  Motion first, second;
  double contactTime = 0.0;    ///< s
  double closingSpeed = 0.0;   ///< m/s, along the normal at contact
  double slidingSpeed = 0.0;   ///< m/s, relative speed across the normal at contact
  double reach = 0.0;          ///< m, sum of the radii
  double firstShare = 0.0;     ///< m_second/(m_first + m_second): the first ball's share
  double relativeSpeed = 0.0;  ///< m/s, |v_first − v_second| before contact
};

inline TwoBallCollision collideTwoBalls(const BallDef& a, const BallDef& b, double seconds) {
  TwoBallCollision result;
  result.reach = a.radius + b.radius;
  // |d + w t| = reach with d = p_a − p_b, w = v_a − v_b: the earlier root of a quadratic.
  const Vec2 d = a.position - b.position;
  const Vec2 w = a.velocity - b.velocity;
  const double ww = dot(w, w);
  const double dw = dot(d, w);
  const double discriminant = dw * dw - ww * (dot(d, d) - result.reach * result.reach);
  result.contactTime = (-dw - std::sqrt(discriminant)) / ww;
  const double t = result.contactTime;
  const Vec2 n = (d + w * t) / result.reach;  // from b to a
  const double un = dot(w, n);                // < 0: approaching
  result.closingSpeed = -un;
  result.slidingSpeed = length(w - un * n);
  result.relativeSpeed = length(w);
  result.firstShare = b.mass / (a.mass + b.mass);
  const Vec2 va = a.velocity - 2.0 * result.firstShare * un * n;
  const Vec2 vb = b.velocity + 2.0 * (a.mass / (a.mass + b.mass)) * un * n;
  const double after = seconds - t;
  result.first = {a.position + a.velocity * t + va * after, va};
  result.second = {b.position + b.velocity * t + vb * after, vb};
  return result;
}

/// A coordinate moving at `speed` from `start` between mirrors at `low` and `high`, `seconds`
/// later: the straight line folded back into [low, high] (a triangle wave).
inline std::pair<double, double> foldBetweenWalls(double start, double speed, double low,
                                                  double high, double seconds) {
  const double span = high - low;
  const double unfolded = std::fmod(start - low + speed * seconds, 2.0 * span);
  const double wrapped = unfolded < 0.0 ? unfolded + 2.0 * span : unfolded;
  return wrapped <= span ? std::pair{low + wrapped, speed}
                         : std::pair{high - (wrapped - span), -speed};
}

/// One ball under linear drag c (1/s), no gravity: v = v0·e^{−ct}, x = x0 + v0(1 − e^{−ct})/c.
inline Motion draggedFlight(const BallDef& ball, double drag, double seconds) {
  const double decay = std::exp(-drag * seconds);
  return {ball.position + ball.velocity * ((1.0 - decay) / drag), ball.velocity * decay};
}

/// How a method may bend a ball's bounces on a floor, for bounding the error: its velocity
/// starts `launchError` (m/s) off, each bounce changes its speed by `speedChange` (m/s) and
/// comes `delay` (s) late. All zero for the exact motion.
struct BounceErrors {
  double launchError = 0.0;
  double speedChange = 0.0;
  double delay = 0.0;
};

/// Height (m) and vertical velocity (m/s) `seconds` after launch of a ball bouncing elastically
/// on a floor its centre reaches at height `floor`, under gravity g < 0 (m/s²).
inline std::pair<double, double> bounceOnFloor(double height, double velocity, double gravity,
                                               double floor, double seconds,
                                               const BounceErrors& errors = {}) {
  double y = height;
  double v = velocity + errors.launchError;
  double t = 0.0;
  for (;;) {
    // y + v τ + ½ g τ² = floor, the later root: τ = (v + √(v² + 2|g|(y − floor)))/|g|.
    const double impactSpeed = std::sqrt(v * v - 2.0 * gravity * (y - floor));
    const double flight = (v + impactSpeed) / -gravity;
    if (t + flight >= seconds) {
      const double tau = seconds - t;
      return {y + v * tau + 0.5 * gravity * tau * tau, v + gravity * tau};
    }
    t += flight + errors.delay;
    if (t >= seconds) return {floor, impactSpeed};
    y = floor;
    v = impactSpeed + errors.speedChange;
  }
}

}  // namespace fooball::testing
