// The capacity search (app/shared/measure): doubling then bisection on a cost function, its limits,
// the CSV of `fooball-cli capacity`, and one real run on a small scale.

#include "capacity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <stop_token>
#include <vector>

#include "capacity_search.h"
#include "fooball/scene_file.h"
#include "fooball/standard_scenes.h"
#include "standard_gas_file.h"
#include "step_timing.h"
#include "test_scenes.h"

namespace fooball::measure {
namespace {

constexpr double kBudget = 1000.0 / 60.0;  // ms

/// A cost of `msPerBall` ms per ball, counting the calls.
struct LinearCost {
  double msPerBall;
  int calls = 0;
  std::optional<double> operator()(std::size_t balls) {
    ++calls;
    return msPerBall * static_cast<double>(balls);
  }
};

TEST(CapacitySearch, FindsTheLargestCountWithinTheBudgetToTheResolution) {
  LinearCost cost{1e-4};  // the budget holds 166'666 balls
  const SearchOutcome outcome = searchCapacity(std::ref(cost), kBudget, {});
  EXPECT_LE(outcome.balls, 166'666u);
  EXPECT_GE(static_cast<double>(outcome.balls), 166'666.0 * (1.0 - 0.02));
  EXPECT_LE(outcome.medianStepMs, kBudget);
  EXPECT_EQ(outcome.medianStepMs, 1e-4 * static_cast<double>(outcome.balls));
  EXPECT_FALSE(outcome.reachedMaxBalls || outcome.timedOut || outcome.cancelled);
  // Doubling from 1000 to 256'000 is 9 counts; bisecting 128'000 … 256'000 to 2% about 6 more.
  EXPECT_LE(outcome.probes.size(), 16u);
  EXPECT_EQ(static_cast<int>(outcome.probes.size()), cost.calls);
  EXPECT_EQ(outcome.probes.front().balls, 1000u);
}

TEST(CapacitySearch, HalvesWhenTheFirstCountIsAlreadyOverTheBudget) {
  LinearCost cost{1.0};  // 16 balls fit, 17 do not
  const SearchOutcome outcome = searchCapacity(std::ref(cost), kBudget, {});
  EXPECT_EQ(outcome.balls, 16u);  // below 50 balls 2% is less than one ball: exact
  EXPECT_EQ(outcome.probes[1].balls, 500u);
}

TEST(CapacitySearch, ReportsZeroWhenNotEvenOneBallFits) {
  const SearchOutcome outcome =
      searchCapacity([](std::size_t) { return std::optional<double>(100.0); }, kBudget, {});
  EXPECT_EQ(outcome.balls, 0u);
  EXPECT_EQ(outcome.probes.back().balls, 1u);
}

TEST(CapacitySearch, StopsAtTheBallLimitAndSaysSo) {
  SearchLimits limits;
  limits.maxBalls = 50'000;
  LinearCost cost{1e-9};
  const SearchOutcome outcome = searchCapacity(std::ref(cost), kBudget, limits);
  EXPECT_EQ(outcome.balls, 50'000u);
  EXPECT_TRUE(outcome.reachedMaxBalls);
}

TEST(CapacitySearch, KeepsTheBestCountWhenTheTimeLimitEndsIt) {
  SearchLimits limits;
  limits.timeLimitSeconds = 35.0;
  double clock = 0.0;  // s; every measurement takes 10 s
  LinearCost slowCost{1e-4};
  const auto cost = [&](std::size_t balls) {
    clock += 10.0;
    return slowCost(balls);
  };
  const SearchOutcome outcome = searchCapacity(cost, kBudget, limits, {}, [&] { return clock; });
  EXPECT_TRUE(outcome.timedOut);
  EXPECT_EQ(outcome.probes.size(), 4u);  // measured at 0, 10, 20 and 30 s
  EXPECT_EQ(outcome.balls, 8000u);
}

TEST(CapacitySearch, EndsWhenTheCostFunctionCancels) {
  int calls = 0;
  const auto cost = [&](std::size_t balls) -> std::optional<double> {
    if (++calls == 3) return std::nullopt;
    return 1e-4 * static_cast<double>(balls);
  };
  const SearchOutcome outcome = searchCapacity(cost, kBudget, {});
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_EQ(outcome.balls, 2000u);
}

TEST(CapacitySearch, ReportsProgressAfterEveryCountInZeroToOne) {
  std::vector<double> fractions;
  LinearCost cost{1e-4};
  const SearchOutcome outcome =
      searchCapacity(std::ref(cost), kBudget, {},
                     [&](const SearchProgress& at) { fractions.push_back(at.fraction); });
  ASSERT_EQ(fractions.size(), outcome.probes.size());
  for (const double fraction : fractions) {
    EXPECT_GE(fraction, 0.0);
    EXPECT_LT(fraction, 1.0);
  }
  EXPECT_GT(fractions.back(), 0.5);
}

TEST(CapacityCsv, HasTheHeaderOfTheDesignAndOneRowPerBackend) {
  std::vector<CapacityResult> results(2);
  results[0].backend = "elastic";
  results[0].outcome.balls = 480'000;
  results[0].outcome.medianStepMs = 16.25;
  results[1].backend = "box2d";
  results[1].outcome.balls = 7'000;
  results[1].outcome.medianStepMs = 15.5;
  std::ostringstream csv;
  writeCapacityCsv(csv, results);
  EXPECT_EQ(csv.str(), "backend,balls,median_step_ms\nelastic,480000,16.25\nbox2d,7000,15.5\n");
}

TEST(CapacitySettingsCheck, RejectsAnOptionNoMeasuredBackendHas) {
  CapacitySettings settings;
  settings.options = {"velocity_iterations=4"};
  const BackendInfo onlyElastic[] = {registeredBackends()[0]};
  ASSERT_EQ(onlyElastic[0].name, "elastic");
  EXPECT_THROW(checkCapacitySettings(onlyElastic, settings), std::invalid_argument);
  settings.options = {"substeps=0"};
  EXPECT_THROW(checkCapacitySettings(onlyElastic, settings), std::invalid_argument);
  settings.options = {"substeps=1"};
  EXPECT_NO_THROW(checkCapacitySettings(onlyElastic, settings));
}

TEST(MeasureCapacity, MeasuresARealBackendWithinSmallLimits) {
  CapacitySettings settings;
  settings.budgetMs = 5.0;
  settings.timedSteps = 3;
  settings.options = {"substeps=1"};
  settings.limits.firstBalls = 500;
  settings.limits.maxBalls = 2000;  // a few hundred µs per step: reached on any machine
  const BackendInfo onlyElastic[] = {registeredBackends()[0]};
  int reports = 0;
  const std::vector<CapacityResult> results =
      measureCapacity(onlyElastic, settings, [&](const CapacityProgress&) { ++reports; });
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].backend, "elastic");
  EXPECT_EQ(results[0].options, std::vector<std::string>{"substeps=1"});
  EXPECT_EQ(results[0].outcome.balls, 2000u);
  EXPECT_TRUE(results[0].outcome.reachedMaxBalls);
  EXPECT_EQ(reports, static_cast<int>(results[0].outcome.probes.size()));
}

TEST(MeasureCapacity, MeasuresOneBackendInTwoSettingsSideBySideLabelledByTheirSpecs) {
  CapacitySettings settings;
  settings.budgetMs = 5.0;
  settings.timedSteps = 3;
  settings.limits.firstBalls = 500;
  settings.limits.maxBalls = 1000;
  const std::string name(registeredBackends()[0].name);
  const RunSpec runs[] = {{name, {"substeps=1"}}, {name, {"substeps=2"}}};
  const std::vector<CapacityResult> results = measureCapacity(runs, settings);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].backend, name + ":substeps=1");
  EXPECT_EQ(results[1].backend, name + ":substeps=2");
  const RunSpec unknown[] = {{name, {"no_such_option=1"}}};
  EXPECT_THROW(checkCapacitySettings(unknown, settings), std::invalid_argument);
}

TEST(CapacityCsv, QuotesASpecWithSeveralOptions) {
  std::vector<CapacityResult> results(1);
  results[0].backend = "box2d:substeps=8,velocity_iterations=20";
  results[0].outcome.balls = 7'000;
  results[0].outcome.medianStepMs = 15.5;
  std::ostringstream csv;
  writeCapacityCsv(csv, results);
  EXPECT_EQ(
      csv.str(),
      "backend,balls,median_step_ms\n\"box2d:substeps=8,velocity_iterations=20\",7000,15.5\n");
}

TEST(MeasureCapacity, AStopRequestEndsTheRun) {
  std::stop_source stop;
  stop.request_stop();
  const std::vector<CapacityResult> results =
      measureCapacity(registeredBackends(), CapacitySettings{}, {}, stop.get_token());
  EXPECT_TRUE(results.empty());
}

/// How many steps of `dt` medianStepMs took, read from how far one free ball at 1 m/s moved.
int stepsTaken(const StepTiming& timing) {
  Scene scene = testing::emptyBox(1000.0, 9.0);
  scene.balls = {testing::ball({1.0, 4.5}, {1.0, 0.0})};
  const auto backend = createBackend("elastic");
  backend->load(scene);
  EXPECT_TRUE(medianStepMs(*backend, timing).has_value());
  std::vector<Vec2> positions(1), velocities(1);
  backend->readState(positions, velocities);
  return static_cast<int>(std::lround((positions[0].x - 1.0) / timing.dt));
}

TEST(StepTiming, RunsTheWarmUpUntimedThenTheTimedSteps) {
  StepTiming timing;
  timing.warmUpSteps = 60;
  timing.timedSteps = 9;
  EXPECT_EQ(stepsTaken(timing), 69);
}

TEST(StepTiming, GivesUpAfterSixWarmUpStepsWhenTheyAreOverTheLimit) {
  StepTiming timing;
  timing.warmUpSteps = 60;
  timing.timedSteps = 9;
  timing.giveUpAboveMs = 0.0;        // every step is over it
  EXPECT_EQ(stepsTaken(timing), 6);  // the first, which is never judged, then 5
}

TEST(CapacitySettingsCheck, WarmsUpForWholeStepsCoveringTheWarmUpTime) {
  CapacitySettings settings;  // 1 s at 1/60 s
  EXPECT_EQ(stepTimingOf(settings).warmUpSteps, 60);
  EXPECT_EQ(stepTimingOf(settings).giveUpAboveMs, 10.0 * settings.budgetMs);
  settings.warmUpSeconds = 0.0;  // still the one step that grows buffers
  EXPECT_EQ(stepTimingOf(settings).warmUpSteps, 1);
  settings.warmUpSeconds = -1.0;
  EXPECT_THROW(checkCapacitySettings(registeredBackends(), settings), std::invalid_argument);
  settings.warmUpSeconds = std::nan("");
  EXPECT_THROW(checkCapacitySettings(registeredBackends(), settings), std::invalid_argument);
}

TEST(StandardGasFile, IsTheCapacityToolsGasAtTwoThousandBallsBitForBit) {
  // docs/scenes/standard-gas-2000.json: the scene of the engines' table in README and
  // docs/accuracy.md, for `fooball-cli compare --scene` and the app's File > Open.
  const Scene file = loadSceneFile(checkout::kStandardGasFile);
  const Scene gas = standardGas(2000, CapacitySettings{}.packingFraction);
  EXPECT_EQ(file.box, gas.box);
  EXPECT_EQ(file.world, gas.world);
  ASSERT_EQ(file.balls.size(), gas.balls.size());
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    EXPECT_EQ(file.balls[i].position, gas.balls[i].position) << "ball " << i;
    EXPECT_EQ(file.balls[i].velocity, gas.balls[i].velocity) << "ball " << i;
    EXPECT_EQ(file.balls[i].radius, gas.balls[i].radius) << "ball " << i;
    EXPECT_EQ(file.balls[i].mass, gas.balls[i].mass) << "ball " << i;
  }
}

}  // namespace
}  // namespace fooball::measure
