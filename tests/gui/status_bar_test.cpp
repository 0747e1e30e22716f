// The status bar at the smallest size the window is made for, with eight runs: every field, the
// limit notice and the rewind timeline side by side without overlapping or being cut, and a
// long message kept clear of the fields.

#include <QLabel>
#include <QSizeGrip>
#include <QSlider>
#include <QStatusBar>

#include "fooball/presets.h"
#include "gui_fixture.h"
#include "readouts/timeline_bar.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/log_slider.h"

namespace fooball::gui::testing {
namespace {

class StatusBar : public GuiTest {
 protected:
  /// The status bar's visible fields, the size grip aside.
  std::vector<QWidget*> fields() const {
    std::vector<QWidget*> shown;
    for (QWidget* field : window->statusBar()->findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) {
      if (field->isVisible() && !qobject_cast<QSizeGrip*>(field)) shown.push_back(field);
    }
    return shown;
  }

  void openEightRunsBeyondALimit() {
    // One substep: beyond elastic's resting-pile limit at 100 m/s² (limit_notice_test.cpp);
    // in half a second there xpbd and chipmunk pass the energy error users care about
    // (kNoticeableEnergyError: −6.8 % and −8.0 %) and box2d and bullet the limit (+11 %, +120 %).
    open(loadPreset(kDefaultPreset), "elastic:substeps=1",
         {"elastic:substeps=2", "elastic:substeps=3", "elastic:substeps=4", "box2d", "xpbd",
          "chipmunk", "bullet"});
    window->resize(1000, 650);
    LogSlider* gravity = window->sidebar()->gravitySlider();
    gravity->slider()->setValue(gravity->positionOf(100.0));
    frames(30);
    QTest::mouseMove(view(), view()->rect().center());
    window->updateStatusBar();
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
  }
};

TEST_F(StatusBar, EveryFieldFitsAt1000x650WithEightRuns) {
  openEightRunsBeyondALimit();
  // The status bar asks for no more than 1000 px. (With eight runs the window itself keeps
  // wider, for the compare strip above the box: the charts' part of issue 38.)
  EXPECT_LE(window->statusBar()->minimumSizeHint().width(), 1000);

  const auto* notice = window->statusBar()->findChild<QLabel*>(QStringLiteral("limitNotice"));
  ASSERT_TRUE(notice->isVisible());
  EXPECT_TRUE(Qt::mightBeRichText(notice->toolTip())) << "rich text wraps in a tooltip";
  // Two notices at once share the room of one (before, each took 300 px and the timeline's
  // "history …" text was cut to "history 42.0 s, 0.0/25").
  const auto* energy = window->statusBar()->findChild<QLabel*>(QStringLiteral("energyNotice"));
  ASSERT_TRUE(energy->isVisible()) << "xpbd's and chipmunk's energy errors";
  const QSlider* timeline = window->timeline().slider();
  ASSERT_TRUE(timeline->isVisible());
  EXPECT_GE(timeline->width(), 80) << "the timeline keeps room to drag";
  for (const QLabel* label : window->timeline().findChildren<QLabel*>()) {
    EXPECT_GE(label->width(), label->sizeHint().width()) << "cut: " << label->text().toStdString();
  }

  const std::vector<QWidget*> shown = fields();
  const QRect bar = window->statusBar()->rect();
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const QRect a = shown[i]->geometry();
    EXPECT_TRUE(bar.contains(a)) << shown[i]->objectName().toStdString();
    if (const auto* label = qobject_cast<const QLabel*>(shown[i])) {
      EXPECT_GE(label->width(), label->sizeHint().width())
          << "cut: " << label->text().toStdString();
    }
    for (std::size_t j = i + 1; j < shown.size(); ++j) {
      EXPECT_FALSE(a.intersects(shown[j]->geometry()))
          << shown[i]->metaObject()->className() << " and " << shown[j]->metaObject()->className();
    }
  }
}

TEST_F(StatusBar, ALongMessageStopsShortOfTheFields) {
  openEightRunsBeyondALimit();
  const QString message = QStringLiteral(
      "A message far longer than the room the status bar leaves it at 1000 px "
      "wide, with eight runs, and then some more words to be sure of it");
  window->messages().showStatus(message);
  EXPECT_EQ(window->messages().status(), message);
  const QString painted = window->statusBar()->currentMessage();
  EXPECT_TRUE(painted.endsWith(QChar(0x2026))) << painted.toStdString();
  int firstField = window->statusBar()->width();
  for (const QWidget* field : fields())
    firstField = std::min(firstField, field->x());
  EXPECT_LT(window->statusBar()->fontMetrics().horizontalAdvance(painted), firstField);
  EXPECT_EQ(window->statusBar()->toolTip(), message) << "whole in the tooltip";
}

}  // namespace
}  // namespace fooball::gui::testing
