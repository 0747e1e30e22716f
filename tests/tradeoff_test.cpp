// The speed/accuracy trade-off (app/shared/measure): the Pareto front, the settings grid, the CSV
// of `fooball-cli tradeoff`, and a short real run against the exact backend.

#include "tradeoff.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stop_token>
#include <string>
#include <vector>

#include "fooball/presets.h"
#include "pareto.h"

namespace fooball::measure {
namespace {

TEST(ParetoFront, KeepsThePointsNothingCheaperBeats) {
  const CostAndError points[] = {
      {1.0, 5.0},                       // cheapest: on the front
      {2.0, 3.0},                       // more accurate than anything cheaper: on
      {3.0, 4.0},                       // beaten by (2, 3)
      {4.0, 1.0},                       // on
      {2.0, 3.0},                       // equal to an earlier point: only the first counts
      {0.5, std::nan("")}, {5.0, 1.0},  // as accurate as (4, 1) and dearer
  };
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{0, 1, 3}));
}

TEST(ParetoFront, OfNoPointsIsEmpty) {
  EXPECT_TRUE(paretoFront({}).empty());
}

TradeoffPoint point(std::string backend, double cost, double trajectoryError, double energyError) {
  TradeoffPoint p{{std::move(backend), {}}};
  p.cpuMsPerSimulatedSecond = cost;
  p.trajectoryError = trajectoryError;
  p.energyError = energyError;
  return p;
}

TEST(TradeoffFronts, AreTakenPerBackend) {
  const TradeoffPoint points[] = {point("a", 1.0, 1.0, 1.0), point("b", 2.0, 2.0, 0.5),
                                  point("a", 3.0, 0.5, 2.0), point("b", 4.0, 3.0, 0.1)};
  EXPECT_EQ(onFront(points, &TradeoffPoint::trajectoryError),
            (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(onFront(points, &TradeoffPoint::energyError),
            (std::vector<bool>{true, true, false, true}));
}

TEST(TradeoffCsv, HasTheDesignsColumnsThenTheErrorsAndTheFronts) {
  TradeoffPoint only = point("elastic", 12.5, 0.25, 1e-12);
  only.setting.options = {"substeps=4"};
  only.momentumError = 2e-16;
  only.maxOverlap = 0.125;
  std::ostringstream csv;
  writeTradeoffCsv(csv, std::vector<TradeoffPoint>{only});
  EXPECT_EQ(csv.str(),
            "backend,settings,cpu_ms_per_sim_s,energy_error,momentum_error,max_overlap,"
            "trajectory_error_m,on_trajectory_front,on_energy_front\n"
            "elastic,substeps=4,12.5,1e-12,2e-16,0.125,0.25,1,1\n");
}

TEST(TradeoffGrid, VariesSubstepsAndIterationsWhereABackendHasThem) {
  const std::vector<TradeoffSetting> grid = tradeoffGrid(registeredBackends());
  for (const BackendInfo& info : registeredBackends()) {
    const auto backend = info.create();
    const OptionSpec* substeps = backend->options().withRole(OptionRole::Substeps);
    const bool iterations = backend->options().withRole(OptionRole::Iterations) != nullptr;
    // substeps 1 … 64, × iterations 2, 8, 32; without substeps, its defaults
    const long expected = substeps == nullptr ? 1 : iterations ? 21 : 7;
    EXPECT_EQ(std::count_if(grid.begin(), grid.end(),
                            [&](const TradeoffSetting& s) { return s.backend == info.name; }),
              expected)
        << info.name;
    const auto first = std::find_if(
        grid.begin(), grid.end(), [&](const TradeoffSetting& s) { return s.backend == info.name; });
    ASSERT_NE(first, grid.end()) << info.name;
    if (substeps != nullptr) {
      EXPECT_EQ(first->options.front(), substeps->name + "=1") << info.name;
    }
  }
  EXPECT_EQ(settingsText({"exact", {}}), "defaults");
  EXPECT_EQ(settingsText({"box2d", {"substeps=2", "velocity_iterations=8"}}),
            "substeps=2 velocity_iterations=8");
}

TEST(MeasureTradeoff, TheExactBackendMatchesItselfAndTheElasticOneComesClose) {
  const Scene scene = loadPreset("head-on");
  const TradeoffSetting grid[] = {{"exact", {}}, {"elastic", {"substeps=8"}}};
  TradeoffSettings settings;
  settings.duration = 0.5;
  settings.compareAt = 0.5;
  settings.timingRepeats = 1;
  int reports = 0;
  const std::vector<TradeoffPoint> points =
      measureTradeoff(scene, grid, settings, [&](const TradeoffProgress&) { ++reports; });
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(reports, 2);
  EXPECT_EQ(points[0].trajectoryError, 0.0);
  EXPECT_LT(points[0].energyError, 1e-12);
  EXPECT_LT(points[0].momentumError, 1e-12);
  EXPECT_GT(points[0].cpuMsPerSimulatedSecond, 0.0);
  EXPECT_LT(points[1].energyError, 1e-9);
  EXPECT_LT(points[1].momentumError, 1e-12);
  EXPECT_LT(points[1].trajectoryError, 0.1);
}

TEST(MeasureTradeoff, RejectsUnknownOptionsBeforeRunningAnything) {
  const TradeoffSetting grid[] = {{"elastic", {"no_such_option=1"}}};
  EXPECT_THROW(measureTradeoff(loadPreset("head-on"), grid, {}), std::invalid_argument);
}

TEST(MeasureTradeoff, AStopRequestEndsTheRunAfterTheSettingUnderWay) {
  const TradeoffSetting grid[] = {
      {"elastic", {"substeps=1"}}, {"elastic", {"substeps=2"}}, {"elastic", {"substeps=4"}}};
  TradeoffSettings settings;
  settings.duration = 0.2;
  settings.timingRepeats = 1;
  std::stop_source stop;
  int reports = 0;
  const std::vector<TradeoffPoint> points = measureTradeoff(
      loadPreset("head-on"), grid, settings,
      [&](const TradeoffProgress&) {
        ++reports;
        stop.request_stop();  // as Cancel does while the first setting is reported
      },
      stop.get_token());
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(reports, 1);
  EXPECT_EQ(points[0].setting.options, std::vector<std::string>{"substeps=1"});
}

TEST(ChaosGrowth, IsOneWhereNothingCollides) {
  Scene scene = loadPreset("head-on");
  scene.world.ballCollisions = false;
  EXPECT_NEAR(chaosGrowth(scene, {}), 1.0, 1e-6);
}

TEST(ChaosGrowth, IsLargeInAGasAfterASecond) {
  TradeoffSettings settings;
  settings.compareAt = 1.0;
  EXPECT_GT(chaosGrowth(loadPreset("gas"), settings), 100.0);
}

}  // namespace
}  // namespace fooball::measure
