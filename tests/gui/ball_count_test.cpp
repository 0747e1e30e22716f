#include <QLabel>
#include <QLocale>
#include <QRegularExpression>
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

TEST_F(BallCount, ARefusalSaysHowManyWouldFitAndThatManyAreAccepted) {
  Scene scene = fooball::testing::emptyBox(2.0, 2.0);
  scene.balls = {fooball::testing::ball({1.0, 1.0}, {0.0, 0.0}, 0.5)};
  open(scene);
  spin(SettingsSidebar::kMaxBallCount);
  QLabel* refusal = window->sidebar()->ballCountRefusal();
  ASSERT_TRUE(refusal->isVisible());
  const QRegularExpressionMatch match =
      QRegularExpression(QStringLiteral("at most (\\S+) fit$")).match(refusal->text());
  ASSERT_TRUE(match.hasMatch()) << refusal->text().toStdString();
  bool ok = false;
  const int most = QLocale().toInt(match.captured(1), &ok);
  ASSERT_TRUE(ok) << match.captured(1).toStdString();
  // 4 − π/4 = 3.21 m² free; new balls shrink to 1% of the 0.5 m ball at most, radius 0.005 m,
  // in lattice cells of (0.005 m · 2 / 0.8)²: 3.21 · 0.16 / 0.005² = 20,573 new balls by area at
  // most, beside the one there.
  EXPECT_GT(most, 100);
  EXPECT_LE(most, 20574);

  spin(most + 1);
  EXPECT_EQ(mainRun().ballCount(), 1u) << "at most means one more is refused";
  EXPECT_TRUE(refusal->isVisible());
  EXPECT_TRUE(refusal->text().endsWith(QStringLiteral("at most %L1 fit").arg(most)))
      << refusal->text().toStdString();

  spin(most);
  EXPECT_EQ(mainRun().ballCount(), std::size_t(most)) << "what the refusal names is accepted";
  EXPECT_FALSE(refusal->isVisible());
  EXPECT_EQ(mainRun().metrics().maxOverlap, 0.0);
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
