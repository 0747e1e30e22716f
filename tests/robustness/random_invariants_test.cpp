// Thousands of random scenes, settings, tools and edits on every registered backend, checking
// the invariants of the backend contract (DESIGN.md) after every step, and at the end the
// energy both ways, the overlaps and that the state saved then reopens; see case_run.h.
// Reproducible: FOOBALL_CASE_SEED=<seed> re-runs one case (printed on failure) on every backend,
// and says so (an error in CI); FOOBALL_SOAK=<cases> runs that many cases instead of the default
// (case_selection.h).

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "backend_profiles.h"
#include "backend_test_name.h"
#include "case_run.h"
#include "case_selection.h"
#include "fooball/scene_file.h"
#include "random_case.h"
#include "registry.h"

namespace fooball::robustness {
namespace {

/// Run time of the default cases, Release on the loaded 2-core VM, one backend at a time: elastic
/// 6 s, xpbd 8 s, chipmunk 19 s, exact 43 s, box2d 71 s (elastic up to 150 s under ctest -j2,
/// where its worker threads wait for the other core); under the sanitizers (500 cases, Box2D and
/// Bullet themselves uninstrumented) 1.9–5.8 s a backend alone. A soak of 10'000 takes 8 s
/// (elastic), 1 minute (exact) and 1–3½ minutes (box2d).
class RandomInvariants : public ::testing::TestWithParam<BackendInfo> {};

TEST_P(RandomInvariants, HoldOnRandomScenesSettingsToolsAndEdits) {
  const BackendInfo& info = GetParam();
  CaseSelection selection = selectCases(std::getenv);
  ASSERT_TRUE(selection.error.empty()) << selection.error;
  const std::size_t cases = testing::profileFor(info.name).randomCases;
  if (cases > 0 && selection.seeds.size() > cases && std::getenv("FOOBALL_SOAK") == nullptr) {
    selection.seeds.resize(cases);  // the row says why (tests/backend_profiles.cpp)
  }
  if (!selection.notice.empty()) {
    std::cout << selection.notice << "\n";
    RecordProperty("case_selection", selection.notice);
  }
  const std::unique_ptr<Backend> prototype = info.create();
  const std::span<const OptionSpec> options = prototype->options().specs();
  const Tolerances tolerances = tolerancesFor(info.name);
  int failures = 0;
  for (const std::uint64_t seed : selection.seeds) {
    const RandomCase c = drawCase(seed, options);
    const std::string violation =
        violationOf(runCase(c, info, tolerances, workCapFor(info.name)), tolerances);
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

INSTANTIATE_TEST_SUITE_P(EveryBackend, RandomInvariants, ::testing::ValuesIn(registeredBackends()),
                         backendTestName);

/// The environment of selectCases, as a table.
class Environment {
 public:
  Environment(std::initializer_list<std::pair<const char*, const char*>> variables)
      : variables_(variables) {}

  const char* operator()(const char* name) const {
    for (const auto& [key, value] : variables_) {
      if (std::string_view(key) == name) return value;
    }
    return nullptr;
  }

 private:
  std::vector<std::pair<const char*, const char*>> variables_;
};

TEST(CaseSelection, RunsTheDefaultCasesOrAsManyAsTheSoakAsks) {
  const CaseSelection plain = selectCases(Environment{});
  ASSERT_EQ(plain.seeds.size(), 2000u);
  EXPECT_EQ(plain.seeds.front(), 1u);
  EXPECT_EQ(plain.seeds.back(), 2000u);
  EXPECT_EQ(plain.notice, "");
  EXPECT_EQ(plain.error, "");
  EXPECT_EQ(selectCases(Environment{{"FOOBALL_SANITIZED", "1"}}).seeds.size(), 500u);
  EXPECT_EQ(selectCases(Environment{{"FOOBALL_SOAK", "10000"}, {"CI", "true"}}).seeds.size(),
            10000u);
  EXPECT_NE(selectCases(Environment{{"FOOBALL_SOAK", "many"}}).error, "");
}

TEST(CaseSelection, ASingleCaseSaysSoAndIsRefusedInCi) {
  const CaseSelection one = selectCases(Environment{{"FOOBALL_CASE_SEED", "417"}});
  EXPECT_EQ(one.seeds, std::vector<std::uint64_t>{417});
  EXPECT_EQ(one.notice, "FOOBALL_CASE_SEED=417: ran case 417 only, not the 2000 default cases");
  EXPECT_EQ(one.error, "");
  for (const char* ci : {"true", "1", "yes"}) {
    const CaseSelection refused =
        selectCases(Environment{{"FOOBALL_CASE_SEED", "417"}, {"CI", ci}});
    EXPECT_TRUE(refused.seeds.empty()) << ci;
    EXPECT_EQ(refused.error,
              "FOOBALL_CASE_SEED=417 is set in CI: the random suite would run that one case "
              "instead of its 2000; unset it")
        << ci;
  }
  for (const char* notCi : {"", "0", "false"}) {
    EXPECT_EQ(selectCases(Environment{{"FOOBALL_CASE_SEED", "417"}, {"CI", notCi}}).error, "")
        << "CI=" << notCi;
  }
  EXPECT_EQ(selectCases(Environment{{"FOOBALL_CASE_SEED", "4x"}}).error,
            "FOOBALL_CASE_SEED=4x: not a case seed (a number)");
}

/// Backends whose profile pins an energy finding.
std::vector<BackendInfo> backendsWithEnergyFindings() {
  std::vector<BackendInfo> backends;
  for (const BackendInfo& info : registeredBackends()) {
    if (testing::profileFor(info.name).energyFinding.seed != 0) backends.push_back(info);
  }
  return backends;
}

/// A finding the profile pins (tests/backend_profiles.cpp, energyFinding): the case changes the
/// energy by what was measured, within the pin both ways. When this fails the method changed:
/// a smaller change, a finding going away, or a larger one; re-measure, and update or remove the
/// pin and the bounds it explains.
class RandomInvariantsKnownFinding : public ::testing::TestWithParam<BackendInfo> {};

TEST_P(RandomInvariantsKnownFinding, ChangesTheEnergyAsPinned) {
  const BackendInfo& info = GetParam();
  const testing::BackendProfile& profile = testing::profileFor(info.name);
  const testing::EnergyFinding& finding = profile.energyFinding;
  const std::unique_ptr<Backend> prototype = info.create();
  const RandomCase c = drawCase(finding.seed, prototype->options().specs());
  ASSERT_NE(c.scene.world.gravity, Vec2{});
  const CaseOutcome outcome = runCase(c, info, profile.robustness, profile.workCap);
  ASSERT_EQ(outcome.stepViolation, "");
  ASSERT_NE(outcome.energyWorld, EnergyWorld::None) << "an isolated case: the method's energy";
  EXPECT_FALSE(outcome.stoppedByWorkCap);
  EXPECT_TRUE(finding.relativeChange.contains(outcome.relativeEnergyChange()))
      << info.name << ", case seed " << finding.seed << ": relative energy change "
      << outcome.relativeEnergyChange() << ", pinned at " << finding.relativeChange.low << " to "
      << finding.relativeChange.high;
}

INSTANTIATE_TEST_SUITE_P(EveryBackendWithAFinding, RandomInvariantsKnownFinding,
                         ::testing::ValuesIn(backendsWithEnergyFindings()), backendTestName);

}  // namespace
}  // namespace fooball::robustness
