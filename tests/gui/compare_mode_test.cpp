#include <QComboBox>

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

}  // namespace
}  // namespace fooball::gui::testing
