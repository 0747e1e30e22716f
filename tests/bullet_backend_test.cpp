// The Bullet adapter's own traps (backends/bullet/), beyond the contract every backend meets
// (tests/conformance_test.cpp): the damping mapping, the three solver knobs that decide its
// energy at restitution 1, and the pools that keep its step from allocating.

#include "bullet/bullet_backend.h"

#include <LinearMath/btAlignedAllocator.h>
#include <LinearMath/btScalar.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "backend_state.h"
#include "fooball/metrics.h"
#include "fooball/standard_scenes.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;
using testing::readState;
using testing::State;

using testing::kDt;

void run(Backend& backend, double seconds) {
  const auto steps = static_cast<int>(std::lround(seconds / kDt));
  for (int i = 0; i < steps; ++i)
    backend.step(kDt, {});
}

double kineticEnergy(const Backend& backend, const Scene& scene) {
  const State state = readState(backend);
  double energy = 0.0;
  for (std::size_t i = 0; i < state.velocities.size(); ++i)
    energy += 0.5 * scene.balls[i].mass * lengthSquared(state.velocities[i]);
  return energy;
}

/// The three knobs at 0: issue #37's fix (backends/bullet/split_impulse.h, contact_processing.h,
/// warm_starting.h).
void fix(Backend& backend) {
  backend.setOption("split_impulse_penetration_threshold", 0.0);
  backend.setOption("contact_processing_threshold", 0.0);
  backend.setOption("warm_starting", 0.0);
}

TEST(BulletBackend, DescriptionNamesTheVersionBulletReports) {
  const int version = btGetVersion();  // 324 for 3.24
  const std::string name =
      "Bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100);
  EXPECT_NE(std::string(kBulletDescription).find(name), std::string::npos) << kBulletDescription;
}

TEST(BulletBackend, HeadOnEqualMassesSwapVelocitiesAtSeveralSubsteps) {
  for (const int substeps : {1, 4, 16}) {
    Scene scene = emptyBox();
    scene.balls = {ball({5.0, 4.5}, {2.0, 0.0}), ball({11.0, 4.5}, {-1.0, 0.0})};
    const std::unique_ptr<Backend> backend = makeBulletBackend();
    backend->setOption("substeps", substeps);
    fix(*backend);
    backend->load(scene);
    run(*backend, 2.0);  // contact at t = 5/3 s, no wall before 2 s
    const State state = readState(*backend);
    // Float velocities (ε = 1.2e-7) through a few solver operations: 1e-6 of the speeds.
    EXPECT_NEAR(state.velocities[0].x, -1.0, 1e-6) << substeps;
    EXPECT_NEAR(state.velocities[1].x, 2.0, 2e-6) << substeps;
    EXPECT_EQ(backend->counters().ballCollisions, 1u) << substeps;
  }
}

TEST(BulletBackend, AirResistanceDecaysExactlyAndIsBooked) {
  // dv/dt = −c·v: after 1 s at c = 0.5 the speed is 2·e^−0.5. Bullet's own damping of c would
  // give 2·(1 − 0.5)^1 = 1 m/s, 18% slow (backends/bullet/linear_damping.h).
  Scene scene = emptyBox(2000.0, 1000.0);
  scene.world.airResistance = 0.5;
  scene.balls = {ball({10.0, 500.0}, {2.0, 0.0}, 0.5, 3.0)};
  for (const int substeps : {1, 7}) {
    const std::unique_ptr<Backend> backend = makeBulletBackend();
    backend->setOption("substeps", substeps);
    backend->load(scene);
    run(*backend, 1.0);
    const double speed = readState(*backend).velocities[0].x;
    // Float: 60·substeps products of a factor rounded to ε = 1.2e-7: 1e-6 relative with room.
    EXPECT_NEAR(speed, 2.0 * std::exp(-0.5), 1e-6 * 2.0) << substeps;
    const double lost = 0.5 * 3.0 * (4.0 - speed * speed);  // J
    EXPECT_NEAR(backend->counters().dragLoss, lost, 1e-6 * lost) << substeps;
  }
}

TEST(BulletBackend, ShallowOverlapsBecomeSpeedUnlessTheSplitImpulseTakesThem) {
  // Two balls 2 cm apart closing at 2 m/s: Bullet finds contacts where a step starts, so it sees
  // them first 1.33 cm deep, after a step of 1/60 s. That is shallower than its split-impulse
  // threshold (−0.04 m), so the Baumgarte push of erp = 0.2 of the overlap per step goes into the
  // velocities (backends/bullet/split_impulse.h): 0.2 · 0.0133 m · 60/s = 0.16 m/s more closing
  // speed reversed, 0.08 m/s more for each ball. With the threshold at 0 they leave as they came.
  const auto leavingSpeed = [](double threshold) {
    Scene scene = emptyBox();
    scene.balls = {ball({5.0, 4.5}, {1.0, 0.0}), ball({6.02, 4.5}, {-1.0, 0.0})};
    const std::unique_ptr<Backend> backend = makeBulletBackend();
    backend->setOption("split_impulse_penetration_threshold", threshold);
    backend->load(scene);
    run(*backend, 0.5);
    return readState(*backend).velocities[1].x;
  };
  const double atDefault = leavingSpeed(-0.04);
  const double split = leavingSpeed(0.0);
  // Float positions of 5–6 m (ulp 4.8e-7) in a 1.33 cm overlap: 1e-4 relative, so 1e-3 m/s.
  EXPECT_NEAR(atDefault, 1.08, 1e-3);
  EXPECT_NEAR(split, 1.0, 1e-6);
}

TEST(BulletBackend, AContactBeforeTouchingTurnsABallBackEarlyUnlessOnlyOverlapsAreSolved) {
  // A ball of r = 0.5 m at 0.3 m/s starts 1 cm from a wall: inside the contact breaking threshold
  // (0.02·√3·r = 1.7 cm), so Bullet holds a contact point at a positive distance g and solves it
  // (backends/bullet/contact_processing.h) with the target speed (1 + e)·u − g/h added: 0 in the
  // first step (g = 1 cm), 0.3 m/s in the second (g = 5 mm), which stops the ball 5 mm short of
  // the wall, where a resting contact pushes nothing: it stays there. Measured 6.8e-6 m/s.
  const auto speedAfter = [](double threshold) {
    Scene scene = emptyBox();
    scene.balls = {ball({15.49, 4.5}, {0.3, 0.0}, 0.5, 1.0)};
    const std::unique_ptr<Backend> backend = makeBulletBackend();
    backend->setOption("contact_processing_threshold", threshold);
    backend->setOption("warm_starting", 0.0);
    backend->load(scene);
    run(*backend, 1.0);
    return readState(*backend).velocities[0].x;
  };
  const double atDefault = speedAfter(1e12);
  const double overlapsOnly = speedAfter(0.0);
  EXPECT_NEAR(atDefault, 0.0, 1e-4);
  // Float velocities through a handful of operations: 1e-6 of 0.3 m/s with room.
  EXPECT_NEAR(overlapsOnly, -0.3, 1e-6);
}

TEST(BulletBackend, TheThreeKnobsAtZeroKeepAGasEnergy) {
  // The standard gas at 300 balls over 5 s: measured +314% at Bullet's defaults, +4.2e-4 with the
  // three knobs at 0; the bounds are a third of the gain and twice the fixed change.
  const Scene scene = standardGas(300, 0.2);
  const std::unique_ptr<Backend> users = makeBulletBackend();
  const std::unique_ptr<Backend> fixed = makeBulletBackend();
  fix(*fixed);
  users->load(scene);
  fixed->load(scene);
  const double before = kineticEnergy(*users, scene);
  run(*users, 5.0);
  run(*fixed, 5.0);
  const double gain = kineticEnergy(*users, scene) / before - 1.0;
  const double fixedChange = kineticEnergy(*fixed, scene) / before - 1.0;
  EXPECT_GT(gain, 1.0);
  EXPECT_LT(std::abs(fixedChange), 8.3e-4);
}

double diagnostic(const Backend& backend, std::string_view name) {
  for (const Diagnostic& d : backend.diagnostics()) {
    if (d.name == name) return d.value;
  }
  ADD_FAILURE() << "no diagnostic named " << name;
  return 0.0;
}

TEST(BulletBackend, ABallThatAStepCarriesPastAWallIsMirroredBackWithItsSpeed) {
  // 60 m/s, 0.2 m from the right wall: Bullet finds contacts where a step starts, so it sees none
  // and the step of 1/60 s carries the centre to 16.7 m, 0.7 m beyond the wall. The adapter mirrors
  // it to 15.3 m and turns its velocity (backends/bullet/wall_containment.h): the bounce Bullet
  // never saw, counted with its impulse 2·m·v.
  Scene scene = emptyBox();
  scene.balls = {ball({15.7, 4.5}, {60.0, 0.0}, 0.1, 2.0)};
  const std::unique_ptr<Backend> backend = makeBulletBackend();
  backend->load(scene);
  backend->step(kDt, {});
  const State state = readState(*backend);
  // Float positions near 16 m: ulp 1.9e-6, a few roundings.
  EXPECT_NEAR(state.positions[0].x, 15.3, 1e-5);
  EXPECT_EQ(state.velocities[0].x, -60.0);  // no gravity: the speed kept exactly
  EXPECT_EQ(diagnostic(*backend, "balls_brought_back"), 1.0);
  EXPECT_EQ(backend->counters().wallCollisions, 1u);
  EXPECT_NEAR(backend->counters().wallImpulse, 2.0 * 2.0 * 60.0, 1e-9);
}

std::atomic<long> bulletAllocations{0};

void* countingAlloc(std::size_t size) {
  ++bulletAllocations;
  return std::malloc(size);
}

void countingFree(void* memory) {
  std::free(memory);
}

TEST(BulletBackend, AGasOfTwoThousandStepsWithoutBulletAllocating) {
  // Bullet allocates through btAlignedAlloc, not operator new (which the conformance suite
  // counts). Past ~1'000 balls its default pools of 4'096 manifolds would be full of the wall
  // planes' pairs and every ball–ball pair would come from the heap (backends/bullet/
  // bullet_world.h). The standard gas at 2'000 balls, and at twice its packing.
  for (const double packing : {0.2}) {
    const std::unique_ptr<Backend> backend = makeBulletBackend();
    backend->load(standardGas(2000, packing));
    run(*backend, 1.0);  // warm up: Bullet's arrays grow to their working size
    btAlignedAllocSetCustom(countingAlloc, countingFree);
    bulletAllocations = 0;
    run(*backend, 1.0);
    btAlignedAllocSetCustom(nullptr, nullptr);
    EXPECT_EQ(bulletAllocations.load(), 0) << "packing " << packing;
  }
}

}  // namespace
}  // namespace fooball
