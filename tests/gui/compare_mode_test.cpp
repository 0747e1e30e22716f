#include <QComboBox>
#include <QSpinBox>
#include <algorithm>
#include <thread>

#include "backend_options_form.h"
#include "compare_readout.h"
#include "gui_fixture.h"
#include "settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

class CompareMode : public GuiTest {};

TEST_F(CompareMode, RunsStartTogetherFromTheCurrentStateAndStepInLockstep) {
  open(fooball::testing::gas(50));
  frames(20);
  const Scene now = mainRun().scene();
  QComboBox* compare = window->sidebar()->compareBox();
  const int box2d = compare->findText(QStringLiteral("box2d"));
  compare->setCurrentIndex(box2d);
  emit compare->activated(box2d);
  ASSERT_EQ(runs().runCount(), 2);
  EXPECT_TRUE(window->compareReadout()->isVisible());
  for (std::size_t i = 0; i < now.balls.size(); ++i) {
    EXPECT_EQ(runs().run(0).positions()[i], now.balls[i].position);
    EXPECT_NEAR(runs().run(1).positions()[i].x, now.balls[i].position.x, 1e-5);
  }
  EXPECT_EQ(runs().run(0).time(), 0.0);
  EXPECT_EQ(runs().run(1).time(), 0.0);
  frames(30);
  EXPECT_EQ(runs().run(0).steps(), runs().run(1).steps());
  EXPECT_GT(runs().run(0).steps(), 0u);
}

TEST_F(CompareMode, SameBackendStaysIdentical) {
  open(fooball::testing::gas(50), QStringLiteral("elastic"), QStringLiteral("elastic"));
  frames(60);
  const Divergence divergence = runs().divergence();
  EXPECT_EQ(divergence.maxPositionDifference, 0.0) << "deterministic backends";
  EXPECT_EQ(divergence.energyDifference, 0.0);
}

TEST_F(CompareMode, DifferentBackendsDivergeAndTheReadoutSaysHowFar) {
  open(fooball::testing::gas(80), QStringLiteral("elastic"), QStringLiteral("box2d"));
  frames(120);
  const Divergence divergence = runs().divergence();
  EXPECT_GT(divergence.maxPositionDifference, 0.0);
  EXPECT_LE(divergence.rmsPositionDifference, divergence.maxPositionDifference);
  EXPECT_TRUE(window->compareReadout()->text().contains(QStringLiteral(" m")));
}

TEST_F(CompareMode, TurningCompareOffLeavesOneRun) {
  open(stillBalls(), QStringLiteral("elastic"), QStringLiteral("exact"));
  QComboBox* compare = window->sidebar()->compareBox();
  compare->setCurrentIndex(0);
  emit compare->activated(0);
  EXPECT_EQ(runs().runCount(), 1);
  EXPECT_FALSE(window->compareReadout()->isVisible());
  frames(5);
}

TEST_F(CompareMode, ElasticRunsShareTheCoresAndTheSidebarShowsEachShare) {
  // The elastic backend's threads option follows the runs: all cores for one run, half each in
  // compare mode, so two runs in lockstep do not oversubscribe the machine.
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const auto threadsOf = [&](int run) {
    return runs().run(run).backend().options().value("threads");
  };
  const auto shownThreads = [&](int run) {
    return window->sidebar()->optionsForm(run)->findChild<QSpinBox*>(
        QStringLiteral("option_threads"));
  };
  open(fooball::testing::gas(50), QStringLiteral("elastic"));
  const auto specs = runs().run(0).backend().options().specs();
  const auto threads = std::find_if(specs.begin(), specs.end(),
                                    [](const OptionSpec& spec) { return spec.name == "threads"; });
  ASSERT_NE(threads, specs.end());
  const double single = threadsOf(0);
  EXPECT_EQ(single, std::min<double>(cores, threads->max));
  ASSERT_NE(shownThreads(0), nullptr);
  EXPECT_EQ(shownThreads(0)->value(), single);

  QComboBox* compare = window->sidebar()->compareBox();
  const int elastic = compare->findText(QStringLiteral("elastic"));
  compare->setCurrentIndex(elastic);
  emit compare->activated(elastic);
  ASSERT_EQ(runs().runCount(), 2);
  const double share = std::max(1, cores / 2);
  for (int run = 0; run < 2; ++run) {
    EXPECT_EQ(threadsOf(run), share) << "run " << run;
    ASSERT_NE(shownThreads(run), nullptr);
    EXPECT_EQ(shownThreads(run)->value(), share) << "run " << run;
  }
  frames(10);
  EXPECT_EQ(runs().divergence().maxPositionDifference, 0.0) << "threads change no result";

  compare->setCurrentIndex(0);
  emit compare->activated(0);
  EXPECT_EQ(threadsOf(0), single) << "one run again: all cores back";
}

}  // namespace
}  // namespace fooball::gui::testing
