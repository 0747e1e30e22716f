#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>

#include "fooball/backend.h"
#include "gui_fixture.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/settings_sidebar.h"
#include "window/window_actions.h"

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
  /// Types `text` over an inspector field's number with real key presses, then Return.
  void type(const char* name, const QString& text) {
    QDoubleSpinBox* box = field(name);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
  }
  /// A key press where the keyboard is now, as a user's would land.
  void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QWidget* focus = QApplication::focusWidget();
    QTest::keyClick(focus != nullptr ? focus : window.get(), key, modifiers);
  }
  /// Ball `index` in every run and the baseline.
  std::vector<BallDef> ballEverywhere(std::size_t index) const {
    return group().ballStates(index).states;
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

TEST_F(BallEditing, ARefusedEditSaysInPlainWordsWhichBallIsInTheWay) {
  open(stillBalls());
  selectBall(0);
  type("inspectorX", QStringLiteral("11.8"));  // 0.2 m from ball 1's centre: 0.8 m deep
  EXPECT_EQ(mainRun().positions()[0], (Vec2{4.0, 4.5}));
  const QLabel* error = inspector()->findChild<QLabel*>(QStringLiteral("inspectorError"));
  const QString expected =
      QStringLiteral("The ball would overlap ball 1 (by 160% of the smaller radius).");
  EXPECT_EQ(error->text(), expected);
  EXPECT_EQ(window->messages().status(), expected);
  type("inspectorX", QStringLiteral("0.3"));
  EXPECT_EQ(error->text(),
            QStringLiteral("The ball would stick out of the box through the left wall."));
}

TEST_F(BallEditing, TheMassFollowsTheRadiusUntilTheMassIsEdited) {
  open(stillBalls());
  selectBall(0);
  const double mass = mainRun().masses()[0];  // π·0.5² kg
  type("inspectorRadius", QStringLiteral("1.0"));
  EXPECT_EQ(mainRun().radii()[0], 1.0);
  EXPECT_EQ(mainRun().masses()[0], 4.0 * mass) << "twice the radius, four times the area";
  EXPECT_NEAR(field("inspectorMass")->value(), 4.0 * mass, 1e-4) << "shown at once";

  type("inspectorMass", QStringLiteral("2.5"));
  type("inspectorRadius", QStringLiteral("0.75"));
  EXPECT_EQ(mainRun().radii()[0], 0.75);
  EXPECT_EQ(mainRun().masses()[0], 2.5) << "a mass the user chose stays";
  EXPECT_EQ(field("inspectorMass")->value(), 2.5);
}

TEST_F(BallEditing, CtrlZUndoesAnEditInEveryRunBitExactlyAndCtrlShiftZRedoesIt) {
  // Moving balls, two methods and the chaos baseline: ball 3 is in a slightly different state in
  // each, and undo must give each its own back.
  open(fooball::testing::gas(20), "elastic", {"exact"});
  frames(90);
  selectBall(3);
  const std::vector<BallDef> before = ballEverywhere(3);
  ASSERT_EQ(before.size(), 3u) << "two runs and the baseline";
  ASSERT_NE(before[0].position, before[2].position);

  type("inspectorVx", QStringLiteral("2.5"));
  for (const BallDef& ball : ballEverywhere(3))
    EXPECT_EQ(ball.velocity.x, 2.5);
  EXPECT_EQ(window->actions().undo()->text(), QStringLiteral("&Undo velocity change of ball 3"));

  press(Qt::Key_Z, Qt::ControlModifier);
  const std::vector<BallDef> undone = ballEverywhere(3);
  for (std::size_t k = 0; k < before.size(); ++k) {
    SCOPED_TRACE("simulation " + std::to_string(k));
    EXPECT_EQ(undone[k].position, before[k].position);
    EXPECT_EQ(undone[k].velocity, before[k].velocity);
    EXPECT_EQ(undone[k].radius, before[k].radius);
    EXPECT_EQ(undone[k].mass, before[k].mass);
  }
  EXPECT_EQ(window->actions().redo()->text(), QStringLiteral("&Redo velocity change of ball 3"));

  press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  for (const BallDef& ball : ballEverywhere(3))
    EXPECT_EQ(ball.velocity.x, 2.5);
}

TEST_F(BallEditing, CtrlZUndoesADeleteAndTheBallComesBackInItsPlace) {
  open(stillBalls(), "elastic", {"exact"});
  selectBall(1);
  QTest::keyClick(view(), Qt::Key_Delete);
  ASSERT_EQ(group().ballCount(), 2u);
  EXPECT_EQ(window->actions().undo()->text(), QStringLiteral("&Undo delete of ball 1"));
  press(Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(group().ballCount(), 3u);
  EXPECT_EQ(window->sidebar()->ballCountBox()->value(), 3);
  for (int run = 0; run < 2; ++run) {
    EXPECT_EQ(runs().run(run).positions()[1], (Vec2{12.0, 4.5}));
    EXPECT_EQ(runs().run(run).positions()[2], (Vec2{8.0, 7.5})) << "the others keep their order";
  }
}

TEST_F(BallEditing, AnUndoThatNoLongerFitsSaysWhyAndChangesNothing) {
  open(stillBalls());
  selectBall(0);
  QTest::keyClick(view(), Qt::Key_Delete);
  BallDef intruder = group().ball(0);  // was ball 1; now where ball 0 was
  intruder.position = {4.0, 4.5};
  runs().setBall(0, intruder);
  press(Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(group().ballCount(), 2u);
  EXPECT_EQ(window->messages().status(),
            QStringLiteral("Cannot undo delete of ball 0: The ball would overlap ball 0 (by "
                           "200% of the smaller radius)."));
  EXPECT_TRUE(window->actions().undo()->isEnabled()) << "still there to try again";
}

TEST_F(BallEditing, AfterEnterSpacePausesAndLeavesTheFieldAsItWas) {
  open(stillBalls());
  selectBall(0);
  type("inspectorVy", QStringLiteral("1.5"));
  EXPECT_TRUE(view()->hasFocus()) << "Enter gives the keyboard back to the box";
  const QString text = field("inspectorVy")->text();
  ASSERT_TRUE(runs().paused());
  press(Qt::Key_Space);
  EXPECT_FALSE(runs().paused());
  EXPECT_EQ(field("inspectorVy")->value(), 1.5);
  EXPECT_EQ(field("inspectorVy")->text(), text);
}

TEST_F(BallEditing, SpaceAndDotReachTheAppWhileANumberFieldMerelyHasFocus) {
  open(stillBalls());
  selectBall(0);
  QDoubleSpinBox* x = field("inspectorX");
  x->setFocus();
  const QString text = x->text();
  QTest::keyClick(x, Qt::Key_Period);
  EXPECT_EQ(mainRun().steps(), 1u) << "'.' stepped";
  QTest::keyClick(x, Qt::Key_Space);
  EXPECT_FALSE(runs().paused()) << "Space continued";
  EXPECT_EQ(x->text(), text);
  EXPECT_TRUE(x->hasFocus());

  // The sidebar's number fields too.
  QSpinBox* count = window->sidebar()->ballCountBox();
  count->setFocus();
  const QString countText = count->text();
  QTest::keyClick(count, Qt::Key_Space);
  EXPECT_TRUE(runs().paused());
  EXPECT_EQ(count->text(), countText);
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
