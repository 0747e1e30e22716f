// Thousands of random scenes, settings, tools and edits on every registered backend, checking
// the invariants of the backend contract (DESIGN.md) after every step; see case_run.h.
// Reproducible: FOOBALL_CASE_SEED=<seed> re-runs one case (printed on failure) on every backend;
// FOOBALL_SOAK=<cases> runs that many cases instead of the default.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "backend_test_name.h"
#include "case_run.h"
#include "fooball/scene_file.h"
#include "random_case.h"
#include "registry.h"

namespace fooball::robustness {
namespace {

/// The case seeds to run: one from FOOBALL_CASE_SEED, else 1…N with N from FOOBALL_SOAK, else
/// 2'000 per backend (Release on a 2-core machine: ~10 s each for exact and box2d, 2 s for
/// elastic alone but up to 25 s under ctest -j2, where its worker threads wait for the other
/// core), or 1'000 under the sanitizers (FOOBALL_SANITIZED=1; ASan + UBSan slow this suite only
/// ~1.5×, Box2D itself being uninstrumented: 19 s for all three under ctest -j2). A soak of
/// 10'000 takes 8 s (elastic), 1 minute (exact) and 1–3½ minutes (box2d).
std::vector<std::uint64_t> caseSeeds() {
  if (const char* seed = std::getenv("FOOBALL_CASE_SEED")) return {std::stoull(seed)};
  std::uint64_t count = 2000;
  if (const char* sanitized = std::getenv("FOOBALL_SANITIZED");
      sanitized != nullptr && std::string_view(sanitized) == "1") {
    count = 1000;
  }
  if (const char* soak = std::getenv("FOOBALL_SOAK")) count = std::stoull(soak);
  std::vector<std::uint64_t> seeds(count);
  for (std::uint64_t i = 0; i < count; ++i)
    seeds[i] = i + 1;
  return seeds;
}

class RandomInvariants : public ::testing::TestWithParam<BackendInfo> {};

TEST_P(RandomInvariants, HoldOnRandomScenesSettingsToolsAndEdits) {
  const BackendInfo& info = GetParam();
  const std::unique_ptr<Backend> prototype = info.create();
  const std::span<const OptionSpec> options = prototype->options().specs();
  int failures = 0;
  for (const std::uint64_t seed : caseSeeds()) {
    const RandomCase c = drawCase(seed, options);
    const std::string violation = runCase(c, info, tolerancesFor(info.name), workCapFor(info.name));
    if (violation.empty()) continue;
    // The first failure in full (re-run it with FOOBALL_CASE_SEED), later ones by seed only.
    if (++failures == 1) {
      ADD_FAILURE() << info.name << ", " << describe(c) << "\n  " << violation
                    << "\n  scene: " << writeScene(c.scene);
    } else {
      ADD_FAILURE() << info.name << ", case seed " << seed << ": " << violation;
    }
  }
}

/// Runs case `seed` on `backend` with the energy checked under gravity too, and expects the
/// energy to grow: a known finding. When this fails the backend keeps energy under gravity:
/// remove the test and the exception in tolerancesFor.
void expectEnergyGrowsUnderGravity(std::string_view backend, std::uint64_t seed) {
  const BackendInfo& info = *std::find_if(registeredBackends().begin(), registeredBackends().end(),
                                          [&](const BackendInfo& b) { return b.name == backend; });
  const RandomCase c = drawCase(seed, info.create()->options().specs());
  ASSERT_TRUE(c.isolated() && c.closed());
  ASSERT_NE(c.scene.world.gravity, Vec2{});
  Tolerances strict = tolerancesFor(backend);
  strict.energyKeptUnderGravity = true;
  strict.energyKeptUnderGravityWithCollisions = true;
  EXPECT_NE(runCase(c, info, strict, workCapFor(backend)).find("energy grew"), std::string::npos);
}

TEST(RandomInvariantsKnownFinding, Box2dGainsEnergyUnderGravity) {
  // 22 balls in a closed 1.9 × 0.94 m box under g = 64 m/s², ball collisions off, 125 steps of
  // 22 ms, 4 substeps: the wall contacts alone raise the energy by 89% (13 ms). 13 of the
  // default 2'000 cases gain more than 5% (up to ×2.1, case 1764).
  expectEnergyGrowsUnderGravity("box2d", 417);
}

TEST(RandomInvariantsKnownFinding, ElasticGainsEnergyUnderGravityWithCollisions) {
  // 83 balls in a closed 0.56 × 0.47 m box under g = 0.64 m/s², 86 steps of 40 ms, one substep:
  // balls pushed into the walls by their neighbours are lifted back to contact, and the energy
  // grows by 6.0e-4 (2 ms). None of the default 2'000 cases gains more than the 1e-9 allowed, 7
  // of the next 18'000 do.
  expectEnergyGrowsUnderGravity("elastic", 2324);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, RandomInvariants, ::testing::ValuesIn(registeredBackends()),
                         backendTestName);

}  // namespace
}  // namespace fooball::robustness
