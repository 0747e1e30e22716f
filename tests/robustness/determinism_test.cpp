// Each backend's trajectory is deterministic and pinned: a fixed scene run twice in one process
// ends bit for bit the same, and a 64-bit hash of its final state equals a constant.
//
// A changed hash means the trajectory changed. That must be an intended change (a new
// integrator, a different collision order, a changed default option): update the constant (the
// backend's row in tests/backend_profiles.cpp) in the same commit and say why. An unintended
// change — a refactoring that reorders floating-point operations, an uninitialised value — shows
// up here first.
//
// The hash is of the exact bits, so it also depends on the compiler and its flags. GCC on x86-64
// uses SSE2 doubles and contracts a*b+c into an FMA only when -march allows FMA instructions
// (the build sets no -march), so Release (-O3) and the sanitizer build (RelWithDebInfo, -O2)
// give the same bits; that is checked by running this test in both. A build with -march=native
// or -ffast-math may legitimately differ: the in-process test still holds there.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include "backend_profiles.h"
#include "backend_state.h"
#include "backend_test_name.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using robustness::backendTestName;
using testing::readState;
using testing::State;

/// FNV-1a over the bytes of every position and velocity, in scene order.
std::uint64_t stateHash(const State& state) {
  std::uint64_t hash = 0xcbf29ce484222325u;
  auto mix = [&hash](double value) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xffu;
      hash *= 0x100000001b3u;
    }
  };
  for (std::size_t i = 0; i < state.positions.size(); ++i) {
    for (const double value :
         {state.positions[i].x, state.positions[i].y, state.velocities[i].x, state.velocities[i].y})
      mix(value);
  }
  return hash;
}

/// 300 balls under gravity with mixed masses, walls on: thousands of ball–ball and wall
/// collisions in 5 s, every code path of a step (free flight, pairs, walls) taken.
Scene pinnedScene() {
  Scene scene = testing::gas(300, 2024);
  scene.world.gravity = {0.0, -9.81};
  for (std::size_t i = 0; i < scene.balls.size(); i += 4)
    scene.balls[i].mass *= 5.0;
  return scene;
}

constexpr int kSteps = 300;  ///< of 1/60 s: 5 s

State finalState(const BackendInfo& info) {
  std::unique_ptr<Backend> backend = info.create();
  backend->load(pinnedScene());
  for (int step = 0; step < kSteps; ++step)
    backend->step(1.0 / 60.0, {});
  return readState(*backend);
}

class Determinism : public ::testing::TestWithParam<BackendInfo> {};

TEST_P(Determinism, SameSceneTwiceGivesTheSameBits) {
  const State first = finalState(GetParam());
  const State second = finalState(GetParam());
  ASSERT_EQ(first.positions.size(), second.positions.size());
  for (std::size_t i = 0; i < first.positions.size(); ++i) {
    ASSERT_EQ(first.positions[i], second.positions[i]) << "ball " << i;
    ASSERT_EQ(first.velocities[i], second.velocities[i]) << "ball " << i;
  }
}

TEST_P(Determinism, FinalStateHashIsPinned) {
  const std::uint64_t pinned = testing::profileFor(GetParam().name).determinismHash;
  const std::uint64_t hash = stateHash(finalState(GetParam()));
  ASSERT_NE(pinned, 0u) << "no pinned hash for backend " << GetParam().name
                        << " in tests/backend_profiles.cpp; its hash is " << hash;
  EXPECT_EQ(hash, pinned) << "the trajectory changed: if intended, pin the new hash in "
                          << "tests/backend_profiles.cpp";
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, Determinism, ::testing::ValuesIn(registeredBackends()),
                         backendTestName);

}  // namespace
}  // namespace fooball
