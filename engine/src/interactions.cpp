#include "fooball/interactions.h"

#include <algorithm>
#include <limits>

namespace fooball {

namespace {

/// Grab is a critically damped spring to the cursor. ω = 25 rad/s follows the hand within
/// ~0.1 s; ω·dt ≤ 0.5 keeps the explicit kick stable at any step size.
constexpr double kGrabAngularFrequency = 25.0;  // rad/s
constexpr double kGrabMaxOmegaDt = 0.5;
/// The slingshot launches at this many m/s per metre of pull per unit of strength (1/s²).
constexpr double kSlingshotGain = 0.2;  // s

}  // namespace

std::optional<std::size_t> nearestBall(Vec2 point, std::span<const Vec2> positions,
                                       std::span<const double> radii) {
  std::optional<std::size_t> nearest;
  double nearestGap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    // Negative inside the ball: a ball under the point beats any ball beside it.
    const double gap = length(positions[i] - point) - radii[i];
    if (gap < nearestGap) {
      nearestGap = gap;
      nearest = i;
    }
  }
  return nearest;
}

std::optional<std::size_t> Interactions::pickTarget(Vec2 point, const BallsView& balls) const {
  if (scope == Scope::Selected) {
    if (selected && *selected < balls.positions.size()) return selected;
    return std::nullopt;
  }
  return nearestBall(point, balls.positions, balls.radii);
}

void Interactions::press(Vec2 point, const BallsView& balls) {
  pressed_ = true;
  cursor_ = point;
  pressPoint_ = point;
  pendingLaunch_.reset();
  const bool actsOnOneBall =
      mode == MouseMode::Grab || mode == MouseMode::Slingshot || scope != Scope::All;
  target_ = actsOnOneBall ? pickTarget(point, balls) : std::nullopt;
}

void Interactions::release(Vec2 point) {
  cursor_ = point;
  if (pressed_ && mode == MouseMode::Slingshot && target_) {
    // Pulled back from the press point, the ball flies the other way.
    pendingLaunch_ = kSlingshotGain * strength * (pressPoint_ - point);
  } else {
    target_.reset();
  }
  pressed_ = false;
}

bool Interactions::active() const {
  const bool cursorPulls = pressed_ && mode != MouseMode::Slingshot &&
                           (target_ || (scope == Scope::All && mode != MouseMode::Grab));
  return !attractors_.empty() || cursorPulls || pendingLaunch_.has_value();
}

void Interactions::forgetBalls() {
  target_.reset();
  selected.reset();
  pendingLaunch_.reset();
}

void Interactions::forces(const BallsView& balls, double dt, std::span<Vec2> forces) {
  std::fill(forces.begin(), forces.end(), Vec2{});
  const std::size_t count = balls.positions.size();

  // Springs: a = strength·(anchor − x), from every permanent attractor on every ball.
  for (const Vec2 attractor : attractors_) {
    for (std::size_t i = 0; i < count; ++i) {
      forces[i] += balls.masses[i] * strength * (attractor - balls.positions[i]);
    }
  }

  if (pendingLaunch_ && target_ && *target_ < count) {
    // One step's force that changes the velocity by exactly the launch Δv.
    forces[*target_] += balls.masses[*target_] / dt * *pendingLaunch_;
  }
  if (pendingLaunch_) {
    pendingLaunch_.reset();
    target_.reset();
  }
  if (!pressed_) return;

  const auto springToCursor = [&](std::size_t i, double sign) {
    forces[i] += sign * balls.masses[i] * strength * (cursor_ - balls.positions[i]);
  };
  switch (mode) {
    case MouseMode::Attract:
    case MouseMode::Repel: {
      const double sign = mode == MouseMode::Attract ? 1.0 : -1.0;
      if (target_) {
        if (*target_ < count) springToCursor(*target_, sign);
      } else if (scope == Scope::All) {
        for (std::size_t i = 0; i < count; ++i)
          springToCursor(i, sign);
      }
      break;
    }
    case MouseMode::Grab:
      if (target_ && *target_ < count) {
        const std::size_t i = *target_;
        const double omega = std::min(kGrabAngularFrequency, kGrabMaxOmegaDt / dt);
        const Vec2 acceleration =
            omega * omega * (cursor_ - balls.positions[i]) - 2.0 * omega * balls.velocities[i];
        forces[i] += balls.masses[i] * acceleration;
      }
      break;
    case MouseMode::Slingshot:
      break;  // the ball is only aimed while held; it launches on release
  }
}

}  // namespace fooball
