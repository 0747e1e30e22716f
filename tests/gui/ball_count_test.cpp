#include <QLabel>
#include <QLocale>
#include <QSpinBox>
#include <QStatusBar>
#include <vector>

#include "gui_fixture.h"
#include "sidebar/settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

class BallCount : public GuiTest {
 protected:
  void spin(int count) { window->sidebar()->ballCountBox()->setValue(count); }
};

TEST_F(BallCount, AddingKeepsTheBallsThereAndPlacesNewOnesWithoutOverlap) {
  open(fooball::testing::gas(30));
  frames(10);
  const std::vector<Vec2> before(mainRun().positions().begin(), mainRun().positions().end());
  spin(80);
  ASSERT_EQ(mainRun().ballCount(), 80u);
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(mainRun().positions()[i], before[i]);
  EXPECT_EQ(mainRun().metrics().maxOverlap, 0.0);
  for (std::size_t i = before.size(); i < 80; ++i) {
    EXPECT_GE(mainRun().radii()[i], 0.1);
    EXPECT_LE(mainRun().radii()[i], 0.2) << "new balls are sized like the ones there";
  }
}

TEST_F(BallCount, RemovingTakesTheNewest) {
  open(stillBalls());
  spin(1);
  ASSERT_EQ(mainRun().ballCount(), 1u);
  EXPECT_EQ(mainRun().positions()[0], (Vec2{4.0, 4.5}));
}

TEST_F(BallCount, MoreThanFitAtTheirSizeAreAddedSmaller) {
  open(fooball::testing::gas(30));
  spin(20000);
  ASSERT_EQ(mainRun().ballCount(), 20000u);
  EXPECT_LT(group().newBallScale(), 1.0);
  EXPECT_LT(mainRun().radii()[19999], 0.1);
  EXPECT_EQ(mainRun().metrics().maxOverlap, 0.0);
  EXPECT_TRUE(window->messages().status().contains(QStringLiteral("size")));
}

TEST_F(BallCount, TooManyToFitShowsAnErrorAndKeepsTheBalls) {
  Scene scene = fooball::testing::emptyBox(2.0, 2.0);
  scene.balls = {fooball::testing::ball({1.0, 1.0}, {0.0, 0.0}, 0.5)};
  open(scene);
  spin(SettingsSidebar::kMaxBallCount);
  EXPECT_EQ(mainRun().ballCount(), 1u);
  EXPECT_EQ(window->sidebar()->ballCountBox()->value(), 1) << "the spinner shows the truth";
  // The reason stays beside the field, under it, rather than flashing in the status bar.
  QLabel* refusal = window->sidebar()->ballCountRefusal();
  ASSERT_TRUE(refusal->isVisible());
  EXPECT_TRUE(refusal->text().contains(QStringLiteral("do not fit")))
      << refusal->text().toStdString();
  EXPECT_TRUE(refusal->text().contains(QLocale().toString(SettingsSidebar::kMaxBallCount)));
  QSpinBox* field = window->sidebar()->ballCountBox();
  const QPoint fieldBottom = field->mapTo(window.get(), QPoint(0, field->height()));
  const QPoint refusalTop = refusal->mapTo(window.get(), QPoint(0, 0));
  EXPECT_GE(refusalTop.y(), fieldBottom.y());
  EXPECT_LT(refusalTop.y() - fieldBottom.y(), 20) << "right under the field";
  EXPECT_EQ(refusalTop.x(), field->mapTo(window.get(), QPoint(0, 0)).x());

  spin(2);
  EXPECT_EQ(mainRun().ballCount(), 2u);
  EXPECT_FALSE(refusal->isVisible()) << "an accepted count clears it";
}

TEST_F(BallCount, ChangesApplyToBothRunsInCompareMode) {
  open(fooball::testing::gas(20), "elastic", {"box2d"});
  frames(20);
  spin(60);
  EXPECT_EQ(runs().run(0).ballCount(), 60u);
  EXPECT_EQ(runs().run(1).ballCount(), 60u);
  EXPECT_EQ(runs().run(1).metrics().maxOverlap, 0.0) << "new balls clear both runs' balls";
  spin(10);
  EXPECT_EQ(runs().run(0).ballCount(), 10u);
  EXPECT_EQ(runs().run(1).ballCount(), 10u);
}

}  // namespace
}  // namespace fooball::gui::testing
