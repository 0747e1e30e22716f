// Long runs of a thermalised hard-disk gas on every pair of backends: energy kept, the same
// collision rate (and the Enskog one), and speeds distributed as 2D Maxwell–Boltzmann
// (Rayleigh), each backend against theory and the two against each other.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "backend_pairs.h"
#include "backend_profiles.h"
#include "backend_state.h"
#include "fooball/hard_disk_theory.h"
#include "fooball/random_balls.h"
#include "kolmogorov_smirnov.h"
#include "record_measurement.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::BackendPair;

using testing::kDt;
constexpr double kRadius = 0.15;  // m, every ball: equal masses, so one kT fits all speeds
constexpr double kAlpha = 1e-3;   // significance of the KS tests

/// 300 equal balls in the 16 × 9 m box, 15% of its area: a dilute gas whose collision time
/// (≈ 0.26 s, see collisionRateEnskog) is short next to the run. Speeds start uniform in
/// 0.5–3 m/s, far from Rayleigh, so agreement with Rayleigh shows the gas thermalised.
Scene thermalGas() {
  Scene scene = testing::emptyBox();
  RandomBalls spec;
  spec.count = 300;
  spec.minRadius = kRadius;
  spec.maxRadius = kRadius;
  spec.seed = 7;
  addRandomBalls(scene, spec);
  return scene;
}

/// Sampling plan. The snapshots are 1 s apart, about four collision times: a ball's speed is
/// then practically uncorrelated with its speed at the last snapshot (each collision redraws
/// it), so the pooled speeds count as independent draws for the KS test. Balls at the same
/// instant are nearly independent in a dilute gas (their one link, the fixed total energy,
/// shifts the distribution by O(1/N)). The sanitizer build needs no shorter plan: the time
/// goes to Box2D, a system library built without sanitizers (the whole suite: ~3 s of CPU in
/// Release, ~4 s under ASan).
struct Sampling {
  double thermalise = 5.0;  ///< s before the first snapshot: ≈ 19 collisions per ball
  double spacing = 1.0;     ///< s between snapshots
  int snapshots = 40;
};

/// What one backend's long run gives.
struct GasRun {
  std::string name;
  double initialEnergy = 0.0;  ///< J per ball, at load
  double meanEnergy = 0.0;     ///< J per ball, over the snapshots
  double finalEnergy = 0.0;    ///< J per ball, at the last snapshot
  double collisionRate = 0.0;  ///< ball–ball collisions per ball per second, between snapshots
  std::vector<double> speeds;  ///< m/s, every ball at every snapshot
};

double energyPerBall(const testing::State& state, double mass) {
  double sum = 0.0;
  for (const Vec2 v : state.velocities)
    sum += 0.5 * mass * lengthSquared(v);
  return sum / static_cast<double>(state.velocities.size());
}

void run(Backend& backend, double seconds) {
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i)
    backend.step(kDt, {});
}

GasRun runGas(const BackendInfo& info, const Scene& scene, const Sampling& sampling) {
  auto backend = testing::createForConsistency(info);
  backend->load(scene);
  const double mass = scene.balls.front().mass;
  const double balls = static_cast<double>(scene.balls.size());
  GasRun result;
  result.name = info.name;
  result.initialEnergy = energyPerBall(testing::readState(*backend), mass);
  run(*backend, sampling.thermalise);
  const auto firstCollisions = backend->counters().ballCollisions;
  for (int snapshot = 0; snapshot < sampling.snapshots; ++snapshot) {
    if (snapshot > 0) run(*backend, sampling.spacing);
    const testing::State state = testing::readState(*backend);
    result.finalEnergy = energyPerBall(state, mass);
    result.meanEnergy += result.finalEnergy / sampling.snapshots;
    for (const Vec2 v : state.velocities)
      result.speeds.push_back(length(v));
  }
  const double window = sampling.spacing * (sampling.snapshots - 1);
  result.collisionRate = 2.0 *
                         static_cast<double>(backend->counters().ballCollisions - firstCollisions) /
                         (balls * window);
  return result;
}

/// Enskog's collision rate per ball at temperature kT (fooball/hard_disk_theory.h: the number
/// density over the box, Henderson's contact value). On this scene the backends measure within
/// 1% of it.
double enskogRate(const Scene& scene, double kT) {
  std::vector<double> radii;
  std::vector<double> masses;
  for (const BallDef& ball : scene.balls) {
    radii.push_back(ball.radius);
    masses.push_back(ball.mass);
  }
  return hardDiskTheory(radii, masses, scene.box, kT).collisionRate;
}

/// Relative kinetic-energy drift a backend may show over the run: its row in
/// tests/backend_profiles.cpp, with the reason.
double energyTolerance(std::string_view backend) {
  return testing::profileFor(backend).gasEnergyDrift;
}

class GasStatistics : public ::testing::TestWithParam<BackendPair> {};

TEST_P(GasStatistics, ThermalisedGasAgreesWithMaxwellBoltzmannAndAcrossBackends) {
  const Scene scene = thermalGas();
  const Sampling sampling;
  GasRun runs[2] = {runGas(GetParam().first, scene, sampling),
                    runGas(GetParam().second, scene, sampling)};
  const double mass = scene.balls.front().mass;
  const double window = sampling.spacing * (sampling.snapshots - 1);  // s
  const double balls = static_cast<double>(scene.balls.size());
  for (GasRun& run : runs) {
    // Energy: per ball, at the end and on average, equal to the start.
    EXPECT_NEAR(run.finalEnergy / run.initialEnergy, 1.0, energyTolerance(run.name)) << run.name;
    EXPECT_NEAR(run.meanEnergy / run.initialEnergy, 1.0, energyTolerance(run.name)) << run.name;

    // Speeds against Rayleigh f(v) = (m v/kT) e^{−m v²/2kT}, kT the mean kinetic energy per
    // ball (two degrees of freedom). kT is estimated from the same samples, which makes the KS
    // test conservative (Lilliefors): it rejects less often than α, never more.
    const double kT = run.meanEnergy;
    const auto rayleigh = [&](double v) { return 1.0 - std::exp(-mass * v * v / (2.0 * kT)); };
    const double n = static_cast<double>(run.speeds.size());
    const double distance = testing::ksDistance(run.speeds, rayleigh);
    EXPECT_LT(distance, testing::ksCriticalDistance(kAlpha, n)) << run.name;
    testing::recordMeasurement(run.name + "_ks_rayleigh", distance);

    // Collision rate against Enskog, within 5σ of the count (Poisson: σ = √C, ~2e4 collisions
    // in the window, 0.7%) plus 3% for a finite box, whose walls both thin the balls next to
    // them (a wall is no partner) and order them (denser contact): every backend measures
    // +0.3% to +1.3% against the theory over the box's area.
    const double enskog = enskogRate(scene, kT);
    const double count = run.collisionRate * balls * window / 2.0;
    EXPECT_NEAR(run.collisionRate / enskog, 1.0, 5.0 / std::sqrt(count) + 0.03)
        << run.name << " at " << run.collisionRate << " collisions per ball and second";
    testing::recordMeasurement(run.name + "_collision_rate_per_ball_s", run.collisionRate);
    testing::recordMeasurement(run.name + "_enskog_rate_per_ball_s", enskog);
    testing::recordMeasurement(run.name + "_energy_drift",
                               run.finalEnergy / run.initialEnergy - 1.0);
    testing::recordMeasurement(run.name + "_mean_energy_drift",
                               run.meanEnergy / run.initialEnergy - 1.0);
  }

  // Between the backends: the same mean kinetic energy per ball (each within its tolerance of
  // the same initial one).
  EXPECT_NEAR(runs[0].meanEnergy / runs[1].meanEnergy, 1.0,
              energyTolerance(runs[0].name) + energyTolerance(runs[1].name));

  // The collision counts differ by chance: σ = √(C₁ + C₂) for two independent Poisson counts,
  // 5σ. (A gas of fixed energy fluctuates less than Poisson, and the two runs share their
  // start, so this errs on the loose side by a little.)
  const double counts = (runs[0].collisionRate + runs[1].collisionRate) * balls * window / 2.0;
  const double rateSigma = std::sqrt(counts) * 2.0 / (balls * window);
  // Less a known difference of a model (BackendProfile::collisionRateOffset).
  const auto rateOf = [](const GasRun& run) {
    return run.collisionRate / (1.0 + testing::profileFor(run.name).collisionRateOffset);
  };
  EXPECT_NEAR(rateOf(runs[0]), rateOf(runs[1]), 5.0 * rateSigma);

  // The two pooled speed samples come from one distribution (two-sample KS).
  const double distance = testing::ksDistance(runs[0].speeds, runs[1].speeds);
  EXPECT_LT(distance,
            testing::ksCriticalDistance(kAlpha, static_cast<double>(runs[0].speeds.size()),
                                        static_cast<double>(runs[1].speeds.size())));
  testing::recordMeasurement("ks_two_sample", distance);
}

// Every pair but those with a backend whose row states why its gas cannot agree
// (BackendProfile::gasStatisticsExemption): no test is made for them, rather than one skipped.
std::vector<testing::BackendPair> pairsWithAThermalisedGas() {
  std::vector<testing::BackendPair> pairs;
  for (const testing::BackendPair& pair : testing::everyBackendPair()) {
    if (testing::profileFor(pair.first.name).gasStatisticsExemption.empty() &&
        testing::profileFor(pair.second.name).gasStatisticsExemption.empty())
      pairs.push_back(pair);
  }
  return pairs;
}

INSTANTIATE_TEST_SUITE_P(EveryBackendPair, GasStatistics,
                         ::testing::ValuesIn(pairsWithAThermalisedGas()), testing::pairName);

}  // namespace
}  // namespace fooball
