#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QWheelEvent>

#include "control/scene_commands.h"
#include "control/scene_session.h"
#include "fooball/scene_file.h"
#include "gui_fixture.h"
#include "readouts/run_counters.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/log_slider.h"

namespace fooball::gui::testing {
namespace {

class Sidebar : public GuiTest {
 protected:
  QScrollArea* scrollArea() const {
    for (QWidget* w = window->sidebar(); w; w = w->parentWidget()) {
      if (auto* area = qobject_cast<QScrollArea*>(w)) return area;
    }
    return nullptr;
  }

  /// `notches` notches of the wheel towards the user over the middle of `target`.
  static void spinWheel(QWidget* target, int notches) {
    const QPointF centre = QRectF(target->rect()).center();
    for (int i = 0; i < notches; ++i) {
      QWheelEvent wheel(centre, target->mapToGlobal(centre), QPoint(), QPoint(0, -120),
                        Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
      QCoreApplication::sendEvent(target, &wheel);
    }
  }
};

TEST_F(Sidebar, WheelOverAnUnfocusedSliderScrollsTheSidebar) {
  Scene scene = stillBalls();
  scene.world.gravity = {0.0, -9.81};
  open(scene);
  window->resize(1000, 650);
  QCoreApplication::processEvents();
  QScrollBar* scrollBar = scrollArea()->verticalScrollBar();
  ASSERT_GT(scrollBar->maximum(), 0) << "the sidebar scrolls at 1000 × 650";
  QSlider* gravity = window->sidebar()->gravitySlider()->slider();
  scrollArea()->ensureWidgetVisible(gravity);
  const int scrolled = scrollBar->value();
  ASSERT_FALSE(gravity->hasFocus());

  spinWheel(gravity, 5);
  EXPECT_DOUBLE_EQ(group().world().gravity.y, -9.81) << "the wheel left gravity alone";
  EXPECT_GT(scrollBar->value(), scrolled) << "and scrolled the sidebar down";
  EXPECT_FALSE(gravity->hasFocus());
}

TEST_F(Sidebar, WheelOverAFocusedSliderChangesIt) {
  Scene scene = stillBalls();
  scene.world.gravity = {0.0, -9.81};
  open(scene);
  window->activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
  QSlider* gravity = window->sidebar()->gravitySlider()->slider();
  gravity->setFocus(Qt::MouseFocusReason);
  ASSERT_TRUE(gravity->hasFocus());
  const int scrolled = scrollArea()->verticalScrollBar()->value();

  spinWheel(gravity, 5);
  EXPECT_LT(-group().world().gravity.y, 9.0) << "focused, the wheel turns gravity down";
  EXPECT_EQ(scrollArea()->verticalScrollBar()->value(), scrolled);
}

TEST_F(Sidebar, KeepsItsWidthAsTheCountsGrow) {
  open(stillBalls(), "elastic", {"box2d"});
  QCoreApplication::processEvents();
  // The sidebar is to the right of the box: were it wider, the box would shrink and move.
  const auto boxLeft = [this] { return view()->mapTo(window.get(), pixelOf({0.0, 0.0})).x(); };
  const int boxLeftBefore = boxLeft();
  const int sidebarLeft = window->sidebar()->mapTo(window.get(), QPoint(0, 0)).x();

  window->sidebar()->ballCountBox()->setValue(100'000);
  ASSERT_EQ(group().ballCount(), 100'000u);
  Metrics large;
  large.ballCollisions = 12'345'678;
  large.wallCollisions = 98'765'432;
  large.maxOverlap = 12.34;
  large.escaped = 100'000;
  window->sidebar()->counters()->showMetrics({large, large});
  QCoreApplication::processEvents();
  QCoreApplication::processEvents();
  EXPECT_EQ(boxLeft(), boxLeftBefore);
  EXPECT_EQ(window->sidebar()->mapTo(window.get(), QPoint(0, 0)).x(), sidebarLeft);
}

TEST_F(Sidebar, CounterLabelsAreWhole) {
  const std::string longSpec = "box2d:substeps=64,velocity_iterations=2";
  open(stillBalls(), "elastic", {longSpec, "chipmunk:iterations=30"});
  QCoreApplication::processEvents();
  const QList<QLabel*> names =
      window->sidebar()->counters()->findChildren<QLabel*>(QStringLiteral("runCounterName"));
  ASSERT_EQ(names.size(), 3);
  for (QLabel* name : names) {
    QTextDocument document;
    document.setHtml(name->text());
    const QString shown = document.toPlainText().remove(QChar(0x200B));
    EXPECT_FALSE(shown.contains(QChar(0x2026))) << shown.toStdString();
    EXPECT_TRUE(shown.endsWith(name->toolTip().section(QStringLiteral(": "), 1)))
        << shown.toStdString();
    EXPECT_GE(name->height(), name->heightForWidth(name->width()))
        << "every wrapped line of " << shown.toStdString() << " shows";
  }
  EXPECT_TRUE(names[1]->toolTip().endsWith(QString::fromStdString(longSpec)));
}

TEST_F(Sidebar, TheTimeStepSetInTheAppStepsAndIsSavedWithTheScene) {
  open(stillBalls(), "elastic", {"box2d"});
  QLineEdit* field = window->sidebar()->dtField();
  EXPECT_EQ(field->text().toDouble(), kDefaultDt);
  field->setText(QStringLiteral("0.001"));
  emit field->editingFinished();
  ASSERT_EQ(group().dt(), 0.001);
  EXPECT_EQ(runs().run(1).dt(), 0.001) << "every run steps with it";
  // Six frames take several steps each (the frame loop caps how many), each of 1 ms.
  frames(6);
  EXPECT_GT(mainRun().steps(), 6u);
  EXPECT_EQ(runs().run(1).steps(), mainRun().steps());
  EXPECT_NEAR(group().time(), 0.001 * double(mainRun().steps()), 1e-12);

  QTemporaryDir directory;
  const QString path = directory.filePath(QStringLiteral("dt.json"));
  ASSERT_TRUE(window->scenes().saveSceneFile(path));
  EXPECT_EQ(loadSceneFile(path.toStdString()).dt, std::optional<double>(0.001));
  ASSERT_TRUE(window->scenes().openPreset(QStringLiteral("default")));
  EXPECT_EQ(group().dt(), kDefaultDt) << "a preset runs at its own, the default";
  EXPECT_EQ(field->text().toDouble(), kDefaultDt);
  ASSERT_TRUE(window->scenes().openSceneFile(path));
  EXPECT_EQ(group().dt(), 0.001) << "reopened with the scene";
  EXPECT_EQ(field->text(), QStringLiteral("0.001"));
  window->session().restart();
  EXPECT_EQ(group().dt(), 0.001) << "a restart keeps the setting";
}

TEST_F(Sidebar, ATimeStepThatIsNoneIsRefusedBesideTheField) {
  open(stillBalls());
  QLineEdit* field = window->sidebar()->dtField();
  for (const char* text : {"0", "-1", "abc", "inf"}) {
    field->setText(QString::fromLatin1(text));
    emit field->editingFinished();
    EXPECT_EQ(group().dt(), kDefaultDt) << text;
    const auto* refusal = window->sidebar()->findChild<QLabel*>(QStringLiteral("dtRefusal"));
    EXPECT_TRUE(refusal->isVisible()) << text;
    EXPECT_TRUE(refusal->text().contains(QString::fromLatin1(text))) << text;
    EXPECT_EQ(field->text().toDouble(), kDefaultDt) << "the field shows the step in use";
  }
}

}  // namespace
}  // namespace fooball::gui::testing
