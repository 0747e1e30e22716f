// runFailureMap: the loop of `fooball-cli failure-map` and Tools → Failure map, with its
// progress and stop hooks, and the scene each point keeps for the app to open.

#include <gtest/gtest.h>

#include <cmath>
#include <stop_token>
#include <string>
#include <vector>

#include "failure_map.h"
#include "registry.h"
#include "sweep_run.h"

namespace fooball::failure_map {
namespace {

std::vector<const SweepSpec*> tunnellingThenCradle() {
  return {&findSweep("tunnelling"), &findSweep("cradle")};
}

TEST(FailureMapRun, RunsEverySweepOnEveryBackendAndReportsEachBeforeItStarts) {
  const std::vector<const SweepSpec*> sweeps = tunnellingThenCradle();
  const BackendInfo backends[] = {backendInfo("elastic"), backendInfo("exact")};
  std::vector<std::string> reported;
  std::vector<double> fractions;
  const std::vector<SweepPoint> points =
      runFailureMap(sweeps, backends, true, [&](const FailureMapProgress& at) {
        reported.push_back(std::string(at.sweep->name) + " on " + std::string(at.backend));
        fractions.push_back(at.fraction);
      });
  EXPECT_EQ(reported, (std::vector<std::string>{"tunnelling on elastic", "tunnelling on exact",
                                                "cradle on elastic", "cradle on exact"}));
  EXPECT_EQ(fractions, (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
  std::vector<SweepPoint> expected;
  for (const SweepSpec* spec : sweeps) {
    for (const BackendInfo& backend : backends) {
      const std::vector<SweepPoint> own = runSweep(*spec, backend.name, true);
      expected.insert(expected.end(), own.begin(), own.end());
    }
  }
  ASSERT_EQ(points.size(), expected.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].sweep, expected[i].sweep);
    EXPECT_EQ(points[i].backend, expected[i].backend);
    EXPECT_EQ(points[i].parameter, expected[i].parameter);
    EXPECT_EQ(points[i].passed, expected[i].passed);
  }
}

TEST(FailureMapRun, AStopRequestEndsItAfterTheSweepUnderWay) {
  const std::vector<const SweepSpec*> sweeps = tunnellingThenCradle();
  const BackendInfo backends[] = {backendInfo("elastic")};
  std::stop_source stop;
  int reports = 0;
  const std::vector<SweepPoint> points = runFailureMap(
      sweeps, backends, true,
      [&](const FailureMapProgress&) {
        ++reports;
        stop.request_stop();  // as Cancel does while the first sweep runs
      },
      stop.get_token());
  EXPECT_EQ(reports, 1);
  EXPECT_EQ(points.size(), runSweep(*sweeps[0], "elastic", true).size());
  for (const SweepPoint& point : points)
    EXPECT_EQ(point.sweep, "tunnelling");
}

TEST(FailureMapRun, EachPointKeepsTheSceneItRan) {
  // The tunnelling sweep's parameter is v·h/r of the shooter, ball 0 of its scene.
  const std::vector<SweepPoint> points = runSweep(findSweep("tunnelling"), "elastic", true);
  const double step = solverStep(*createBackend("elastic"), kFrameDt);
  ASSERT_FALSE(points.empty());
  for (const SweepPoint& point : points) {
    ASSERT_FALSE(point.scene.balls.empty()) << point.variant;
    const BallDef& shooter = point.scene.balls[0];
    EXPECT_NEAR(length(shooter.velocity) * step / shooter.radius, point.parameter,
                1e-9 * point.parameter)
        << point.variant;
  }
  // Every sweep keeps a scene with balls for every point.
  for (const SweepSpec& spec : sweepSpecs()) {
    for (const SweepPoint& point : runSweep(spec, "elastic", true))
      EXPECT_FALSE(point.scene.balls.empty()) << spec.name << " at " << point.parameter;
  }
}

}  // namespace
}  // namespace fooball::failure_map
