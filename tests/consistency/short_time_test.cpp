// Short runs of simple scenes, before chaos sets in, on every pair of backends: each backend
// against the closed form, and the two against each other, within bounds derived from each
// method's known errors (method_errors.h; each backend's model is its row in
// tests/backend_profiles.cpp). Two backends may differ by the sum of their bounds.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "backend_pairs.h"
#include "backend_profiles.h"
#include "backend_state.h"
#include "closed_forms.h"
#include "method_errors.h"
#include "record_measurement.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::BackendPair;
using testing::ball;
using testing::emptyBox;
using testing::MethodError;
using testing::Motion;
using testing::State;

using testing::kDt;

/// How far one backend's ball may lie from the closed form, per axis: m and m/s.
struct Bound {
  Vec2 position;
  Vec2 velocity;
  /// The same in every direction.
  static Bound isotropic(double position, double velocity) {
    return {{position, position}, {velocity, velocity}};
  }
};

/// Expects |difference| ≤ bound on each axis.
void expectWithin(Vec2 difference, Vec2 bound, const std::string& what) {
  EXPECT_LE(std::abs(difference.x), bound.x) << what << " x";
  EXPECT_LE(std::abs(difference.y), bound.y) << what << " y";
}

/// The bound of ball `index` for a backend with these errors.
using BoundOf = std::function<Bound(const MethodError& error, std::size_t index)>;

/// One backend's state after running a scene.
struct BackendRun {
  std::string name;
  MethodError error;
  State state;
};

BackendRun runScene(const BackendInfo& info, const Scene& scene, double seconds) {
  auto backend = testing::createForConsistency(info);
  const MethodError error =
      testing::methodError(testing::profileFor(info.name).methodError, *backend, kDt);
  backend->load(scene);
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i)
    backend->step(kDt, {});
  return {std::string(info.name), error, testing::readState(*backend)};
}

class ShortTime : public ::testing::TestWithParam<BackendPair> {
 protected:
  /// Runs `scene` for `seconds` on both backends of the pair and checks every ball against
  /// `exact` (scene order) within its bound, and the backends against each other within the
  /// sum of their bounds. The largest differences are recorded as test properties.
  void expectAgreement(const Scene& scene, double seconds, const std::vector<Motion>& exact,
                       const BoundOf& boundOf) {
    const BackendRun runs[2] = {runScene(GetParam().first, scene, seconds),
                                runScene(GetParam().second, scene, seconds)};
    double pairPosition = 0.0;
    double pairVelocity = 0.0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
      const std::string ball = "ball " + std::to_string(i);
      Bound bounds[2];
      for (int k = 0; k < 2; ++k) {
        const BackendRun& run = runs[k];
        bounds[k] = boundOf(run.error, i);
        const Vec2 position = run.state.positions[i] - exact[i].position;
        const Vec2 velocity = run.state.velocities[i] - exact[i].velocity;
        expectWithin(position, bounds[k].position, run.name + " " + ball + " position");
        expectWithin(velocity, bounds[k].velocity, run.name + " " + ball + " velocity");
        const std::string key = run.name + "_ball" + std::to_string(i);
        testing::recordMeasurement(key + "_position_error_m", length(position));
        testing::recordMeasurement(key + "_velocity_error_m_per_s", length(velocity));
        testing::recordMeasurement(key + "_position_bound_m",
                                   std::max(bounds[k].position.x, bounds[k].position.y));
        testing::recordMeasurement(key + "_velocity_bound_m_per_s",
                                   std::max(bounds[k].velocity.x, bounds[k].velocity.y));
      }
      const Vec2 position = runs[0].state.positions[i] - runs[1].state.positions[i];
      const Vec2 velocity = runs[0].state.velocities[i] - runs[1].state.velocities[i];
      expectWithin(position, bounds[0].position + bounds[1].position, "pair " + ball + " position");
      expectWithin(velocity, bounds[0].velocity + bounds[1].velocity, "pair " + ball + " velocity");
      pairPosition = std::max(pairPosition, length(position));
      pairVelocity = std::max(pairVelocity, length(velocity));
    }
    testing::recordMeasurement("max_position_difference_m", pairPosition);
    testing::recordMeasurement("max_velocity_difference_m_per_s", pairVelocity);
  }

  /// Two balls that meet once, well before `seconds` and before any wall.
  void expectTwoBallAgreement(const BallDef& a, const BallDef& b, double seconds) {
    Scene scene = emptyBox();
    scene.balls = {a, b};
    const testing::TwoBallCollision exact = testing::collideTwoBalls(a, b, seconds);
    ASSERT_GT(exact.contactTime, 0.0);
    ASSERT_LT(exact.contactTime, seconds);
    const double fastest = std::max({length(a.velocity), length(b.velocity),
                                     length(exact.first.velocity), length(exact.second.velocity)});
    expectAgreement(scene, seconds, {exact.first, exact.second},
                    [&](const MethodError& error, std::size_t index) {
                      const double share = index == 0 ? exact.firstShare : 1.0 - exact.firstShare;
                      return twoBallBound(error, exact, share, seconds, fastest);
                    });
  }

  /// A time-stepped method finds the contact at depth D ≤ contactDepth(u), τ = D/u late.
  /// - Along the normal the separation lags by contactLag·D, shared by the balls as the
  ///   separation correction is: `share` = m_other/(m_a + m_b) of it moves this ball.
  /// - The normal is taken from the centres at detection, d' = reach·n − u·τ·n + w·τ·t (w the
  ///   sliding speed), turned by θ = atan(w·τ/(reach − D)) from the true one. The impulse
  ///   2·share·(v_rel·n)·n changes by at most 2·share·|v_rel|·θ per radian of turn, and that
  ///   velocity error carries the ball off for the rest of the run.
  static Bound twoBallBound(const MethodError& error, const testing::TwoBallCollision& exact,
                            double share, double seconds, double fastest) {
    const double depth = error.contactDepth(exact.closingSpeed, false);
    const double lateness = depth / exact.closingSpeed;
    const double turn = std::atan(exact.slidingSpeed * lateness / (exact.reach - depth));
    const double velocity = 2.0 * share * exact.relativeSpeed * turn;
    const double position =
        share * error.contactLag * depth + velocity * (seconds - exact.contactTime);
    return Bound::isotropic(position + error.positionRounding(seconds, fastest),
                            velocity + error.velocityRounding(seconds, fastest));
  }
};

TEST_P(ShortTime, HeadOnEqualMassesSwapVelocities) {
  // Gap 5.7 m closing at 3.3 m/s: contact at 1.727 s, not on a step boundary.
  expectTwoBallAgreement(ball({4.3, 4.5}, {2.0, 0.0}), ball({11.0, 4.5}, {-1.3, 0.0}), 2.5);
}

TEST_P(ShortTime, HeadOnUnequalMassesExchangeMomentum) {
  // 1 kg meets 3 kg: v' = −2.95 and 0.35 m/s.
  expectTwoBallAgreement(ball({4.3, 4.5}, {2.0, 0.0}, 0.5, 1.0),
                         ball({11.0, 4.5}, {-1.3, 0.0}, 0.5, 3.0), 2.5);
}

TEST_P(ShortTime, GlancingCollisionDeflectsAlongTheLineOfCentres) {
  // Centres 0.6 m apart across the motion, 2/3 of the reach (0.9 m): the normal is 42° off
  // the line of motion. 1 kg meets 2 kg.
  expectTwoBallAgreement(ball({4.3, 4.5}, {2.0, 0.0}, 0.5, 1.0),
                         ball({11.0, 5.1}, {-1.3, 0.0}, 0.4, 2.0), 2.5);
}

TEST_P(ShortTime, BallHitsAWallAtAnAngle) {
  // Reaches the right wall (centre at 15.5 m) after 1.129 s; the top wall is not reached.
  Scene scene = emptyBox();
  const BallDef b = ball({12.0, 3.0}, {3.1, 1.7});
  scene.balls = {b};
  const double seconds = 2.0;
  const auto [x, vx] =
      testing::foldBetweenWalls(b.position.x, b.velocity.x, b.radius, 16.0 - b.radius, seconds);
  const auto [y, vy] =
      testing::foldBetweenWalls(b.position.y, b.velocity.y, b.radius, 9.0 - b.radius, seconds);
  const double speed = length(b.velocity);
  // The wall turns only the normal speed u = 3.1 m/s around; the lag is along the normal.
  expectAgreement(scene, seconds, {{{x, y}, {vx, vy}}}, [&](const MethodError& error, std::size_t) {
    const double rounding = error.positionRounding(seconds, speed);
    const double lag = error.wallLag * error.contactDepth(b.velocity.x, true);
    const double velocity = error.velocityRounding(seconds, speed);
    return Bound{{lag + rounding, rounding}, {velocity, velocity}};
  });
}

TEST_P(ShortTime, BallBouncesUnderGravity) {
  // Dropped from 4 m (centre), radius 0.5 m: impact at 8.29 m/s every 1.69 s, three bounces
  // (0.845, 2.53, 4.22 s) before 4.5 s. A small sideways speed that no wall sees.
  Scene scene = emptyBox();
  const double g = -9.81;
  scene.world.gravity = {0.0, g};
  const BallDef b = ball({8.0, 4.0}, {0.4, 0.0});
  scene.balls = {b};
  const double seconds = 4.5;
  const double floor = b.radius;
  const auto [y, vy] = testing::bounceOnFloor(b.position.y, 0.0, g, floor, seconds);
  const double impact = std::sqrt(-2.0 * g * (b.position.y - floor));
  const Motion exact{{b.position.x + b.velocity.x * seconds, y}, {b.velocity.x, vy}};
  expectAgreement(scene, seconds, {exact}, [&](const MethodError& error, std::size_t) {
    // From the method's errors (see BounceErrors), each bounce with the sign it has:
    // - elastic reflects the ball at the exact time it crossed the floor, from the quadratic
    //   of its parabola (backends/elastic/wall_bounce.h): no error beyond rounding;
    // - Box2D flies by semi-implicit Euler (v += h·g, then x += h·v): its positions follow
    //   exactly the parabola of a launch velocity h·g/2 off the reported one. It reverses the
    //   velocity after that step's gravity increment, so a bounce keeps this parabola's speed.
    //   It finds the contact at depth D ≤ contactDepth(u) and flies out from there at the
    //   impact speed: the ball of a parabola with |g|·D less energy per kg (speed |g|D/u
    //   lower), which passes the floor 2D/u after the exact bounce (lag 2D = wallLag·D).
    const double h = error.solverStep;
    testing::BounceErrors worst;
    if (error.eulerFlight) {
      const double lag = error.wallLag * error.contactDepth(impact, true);  // m
      worst = {0.5 * g * h, 0.5 * g * lag / impact, lag / impact};
    }
    // The largest departure with each bounce error anywhere between none and its worst (they
    // are small, so the extremes lie at the ends).
    double position = 0.0;  // m, height
    double velocity = 0.0;  // m/s, vertical
    for (const double speed : {0.0, 1.0}) {
      for (const double delay : {0.0, 1.0}) {
        const auto [by, bvy] = testing::bounceOnFloor(
            b.position.y, 0.0, g, floor, seconds,
            {worst.launchError, speed * worst.speedChange, delay * worst.delay});
        position = std::max(position, std::abs(by - y));
        velocity = std::max(velocity, std::abs(bvy - vy));
      }
    }
    // Box2D reports the velocity h·g/2 off the parabola its positions follow.
    if (error.eulerFlight) velocity += 0.5 * -g * h;
    // Sideways the flight is free: rounding only.
    const double positionRounding = error.positionRounding(seconds, impact);
    const double velocityRounding = error.velocityRounding(seconds, impact);
    return Bound{{positionRounding, position + positionRounding},
                 {velocityRounding, velocity + velocityRounding}};
  });
}

TEST_P(ShortTime, DragDecaysVelocityExponentially) {
  // c = 0.7/s for 2 s: the speed falls to e^{−1.4} = 25% of 3.16 m/s, 3.2 m travelled.
  Scene scene = emptyBox();
  const double drag = 0.7;
  scene.world.airResistance = drag;
  const BallDef b = ball({3.0, 3.0}, {3.0, 1.0});
  scene.balls = {b};
  const double seconds = 2.0;
  const Motion exact = testing::draggedFlight(b, drag, seconds);
  const double speed = length(b.velocity);
  expectAgreement(scene, seconds, {exact}, [&](const MethodError& error, std::size_t) {
    // Box2D's damping multiplies v by exactly e^{−ch} per step (the adapter's c'), but
    // positions advance by h·v after it: the displacement is ch/(e^{ch} − 1) ≥ 1 − ch/2 of
    // the exact one. elastic and exact integrate the exponential in closed form.
    const Vec2 travel = exact.position - b.position;  // m
    const double euler = error.eulerFlight ? 0.5 * drag * error.solverStep : 0.0;
    const double rounding = error.positionRounding(seconds, speed);
    const double velocity = error.velocityRounding(seconds, speed);
    return Bound{{euler * std::abs(travel.x) + rounding, euler * std::abs(travel.y) + rounding},
                 {velocity, velocity}};
  });
}

INSTANTIATE_TEST_SUITE_P(EveryBackendPair, ShortTime,
                         ::testing::ValuesIn(testing::everyBackendPair()), testing::pairName);

}  // namespace
}  // namespace fooball
