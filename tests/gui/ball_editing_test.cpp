#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>

#include "ball_inspector.h"
#include "fooball/backend.h"
#include "gui_fixture.h"
#include "settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

class BallEditing : public GuiTest {
 protected:
  BallInspector* inspector() const { return window->sidebar()->inspector(); }
  QDoubleSpinBox* field(const char* name) const {
    return inspector()->findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
  }
  /// Types `value` into an inspector field and presses Return, as a user would.
  void edit(const char* name, double value) {
    QDoubleSpinBox* box = field(name);
    box->setFocus();
    box->setValue(value);
    QTest::keyClick(box, Qt::Key_Return);
  }
  void selectBall(std::size_t index) {
    runs().setPaused(true);
    QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf(mainRun().positions()[index]));
    ASSERT_EQ(group().selected(), index);
  }
};

TEST_F(BallEditing, TheDeleteKeyDeletesTheSelectedBallUnlessAFieldIsBeingEdited) {
  open(stillBalls());
  selectBall(1);
  QDoubleSpinBox* x = field("inspectorX");
  x->setFocus();
  x->selectAll();
  QTest::keyClick(x, Qt::Key_Delete);
  EXPECT_EQ(group().ballCount(), 3u) << "Delete in a field edits the field";
  QTest::keyClick(window.get(), Qt::Key_Escape);
  EXPECT_TRUE(view()->hasFocus()) << "Esc gives the keyboard back to the box";
  QTest::keyClick(view(), Qt::Key_Delete);
  EXPECT_EQ(group().ballCount(), 2u);
  EXPECT_FALSE(group().selected());
}

TEST_F(BallEditing, AfterEditingAFieldAClickInTheBoxGivesSpaceBackToPause) {
  open(stillBalls());
  selectBall(0);
  edit("inspectorVx", 1.0);
  ASSERT_TRUE(runs().paused());
  QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf({8.0, 1.0}));  // no ball there
  EXPECT_TRUE(view()->hasFocus());
  QTest::keyClick(view(), Qt::Key_Space);
  EXPECT_FALSE(runs().paused()) << "Space paused or continued, it typed into no field";
}

TEST_F(BallEditing, ClickingABallWhilePausedSelectsIt) {
  open(stillBalls());
  runs().setPaused(true);
  QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf({12.2, 4.6}));
  EXPECT_EQ(group().selected(), 1u);
  EXPECT_TRUE(inspector()->isVisible());
  EXPECT_EQ(inspector()->ballIndex(), 1u);
  EXPECT_DOUBLE_EQ(field("inspectorX")->value(), 12.0);

  QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf({1.0, 1.0}));
  EXPECT_FALSE(group().selected().has_value()) << "clicking empty space clears the selection";
  EXPECT_FALSE(inspector()->isVisible());
}

TEST_F(BallEditing, ClickingWhileRunningUsesTheToolInstead) {
  open(stillBalls());
  QTest::mouseClick(view(), Qt::LeftButton, {}, pixelOf({12.0, 4.5}));
  EXPECT_FALSE(group().selected().has_value());
}

TEST_F(BallEditing, InspectorEditChangesTheBallInTheBackend) {
  open(stillBalls());
  selectBall(2);
  edit("inspectorVx", 1.5);
  edit("inspectorRadius", 0.75);
  edit("inspectorMass", 3.0);
  // What the backend holds: a fresh read of its state, not the simulation's copy.
  std::vector<Vec2> positions(mainRun().ballCount());
  std::vector<Vec2> velocities(mainRun().ballCount());
  mainRun().backend().readState(positions, velocities);
  EXPECT_DOUBLE_EQ(velocities[2].x, 1.5);
  EXPECT_DOUBLE_EQ(mainRun().radii()[2], 0.75);
  EXPECT_DOUBLE_EQ(mainRun().masses()[2], 3.0);
  runs().stepOnce();
  EXPECT_NEAR(mainRun().positions()[2].x, 8.0 + 1.5 * mainRun().dt(), 1e-12);
}

TEST_F(BallEditing, InvalidEditShowsTheErrorAndKeepsTheBall) {
  open(stillBalls());
  selectBall(0);
  edit("inspectorX", 11.8);  // would overlap ball 1 at x = 12
  EXPECT_EQ(mainRun().positions()[0], (Vec2{4.0, 4.5}));
  const QLabel* error = inspector()->findChild<QLabel*>(QStringLiteral("inspectorError"));
  EXPECT_TRUE(error->isVisible());
  EXPECT_TRUE(error->text().contains(QStringLiteral("overlap"))) << error->text().toStdString();
  EXPECT_DOUBLE_EQ(field("inspectorX")->value(), 4.0) << "the inspector shows the kept state";
}

TEST_F(BallEditing, DeleteRemovesTheBall) {
  open(stillBalls());
  selectBall(1);
  inspector()->findChild<QPushButton*>(QStringLiteral("inspectorDelete"))->click();
  ASSERT_EQ(mainRun().ballCount(), 2u);
  EXPECT_EQ(mainRun().backend().ballCount(), 2u);
  EXPECT_EQ(mainRun().positions()[1], (Vec2{8.0, 7.5})) << "the others keep their order";
  EXPECT_FALSE(group().selected().has_value());
}

TEST_F(BallEditing, EditsApplyToTheCompareRunAlike) {
  open(stillBalls(), "elastic", {"exact"});
  selectBall(0);
  edit("inspectorVy", -2.0);
  EXPECT_DOUBLE_EQ(runs().run(0).velocities()[0].y, -2.0);
  EXPECT_DOUBLE_EQ(runs().run(1).velocities()[0].y, -2.0);
  inspector()->findChild<QPushButton*>(QStringLiteral("inspectorDelete"))->click();
  EXPECT_EQ(runs().run(0).ballCount(), 2u);
  EXPECT_EQ(runs().run(1).ballCount(), 2u);
}

TEST_F(BallEditing, SingleStepWhilePausedAdvancesOneStep) {
  open(stillBalls());
  runs().setPaused(true);
  frames(10);
  EXPECT_EQ(mainRun().steps(), 0u) << "paused";
  runs().stepOnce();
  EXPECT_EQ(mainRun().steps(), 1u);
}

}  // namespace
}  // namespace fooball::gui::testing
