// What a preset teaches, on screen: its "what to look for" caption above the box (hidden and
// shown again from its close button and the View menu, absent for scene files), the live
// collision count of mass-ratio read from each run's own counters, and one box per wall.

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QRegularExpression>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "control/scene_session.h"
#include "fooball/presets.h"
#include "gui_fixture.h"
#include "readouts/run_counters.h"
#include "sidebar/settings_sidebar.h"
#include "widgets/view_text.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

using Caption = SimulationView::Caption;

class PresetCaption : public GuiTest {
 protected:
  /// Picks `name` in the sidebar's preset dropdown, as a user does.
  void choosePreset(const QString& name) {
    auto* box = window->sidebar()->findChild<QComboBox*>(QStringLiteral("presetBox"));
    const int index = box->findText(name);
    ASSERT_GE(index, 0) << name.toStdString();
    box->setCurrentIndex(index);
    emit box->activated(index);
    ASSERT_EQ(window->session().presetName(), name);
  }

  std::vector<Caption> captionsOf(Caption::Kind kind) const {
    std::vector<Caption> found;
    for (const Caption& caption : view()->captions()) {
      if (caption.kind == kind) found.push_back(caption);
    }
    return found;
  }

  QCheckBox* wallBox(const char* name) const {
    return window->sidebar()->findChild<QCheckBox*>(QString::fromLatin1(name));
  }

  /// Each run's collision count as the view shows it equals the run's own counters.
  void expectCountsOfEveryRun() const {
    const std::vector<Caption> counts = captionsOf(Caption::Kind::Collisions);
    ASSERT_EQ(int(counts.size()), runs().runCount());
    static const QRegularExpression pattern(
        QStringLiteral("^(\\d+) ball–ball \\+ (\\d+) wall = (\\d+) collisions$"));
    for (const Caption& caption : counts) {
      const QRegularExpressionMatch match = pattern.match(caption.text);
      ASSERT_TRUE(match.hasMatch()) << caption.text.toStdString();
      const BackendCounters counters = runs().run(caption.runIndex).counters();
      EXPECT_EQ(match.captured(1).toULongLong(), counters.ballCollisions);
      EXPECT_EQ(match.captured(2).toULongLong(), counters.wallCollisions);
      EXPECT_EQ(match.captured(3).toULongLong(), counters.ballCollisions + counters.wallCollisions);
      EXPECT_TRUE(view()->rect().contains(caption.rect));
      EXPECT_FALSE(caption.rect.intersects(view()->transformForRun(0).boxRect()));
    }
  }
};

TEST_F(PresetCaption, MassRatioCountsItsCollisionsLiveFromTheRunsOwnCounters) {
  open(stillBalls());
  EXPECT_TRUE(captionsOf(Caption::Kind::Collisions).empty());
  choosePreset(QStringLiteral("mass-ratio"));
  expectCountsOfEveryRun();
  EXPECT_TRUE(captionsOf(Caption::Kind::Collisions).front().text.startsWith(QStringLiteral("0 ")));
  // 40 s, a frame at a time, reading the count every second as it climbs.
  for (int second = 0; second < 40; ++second) {
    frames(60);
    expectCountsOfEveryRun();
  }
  EXPECT_EQ(captionsOf(Caption::Kind::Collisions).front().text,
            QStringLiteral("16 ball–ball + 15 wall = 31 collisions"));
  // The sidebar's Counters table says the same.
  EXPECT_TRUE(
      window->sidebar()->counters()->text().contains(QStringLiteral("16 ball–ball, 15 wall")));
  // Other presets count nothing beside their caption.
  choosePreset(QStringLiteral("head-on"));
  EXPECT_TRUE(captionsOf(Caption::Kind::Collisions).empty());
}

TEST_F(PresetCaption, MassRatioCountsEveryRunInCompareMode) {
  open(stillBalls(), "elastic", {"exact"});
  choosePreset(QStringLiteral("mass-ratio"));
  for (int second = 0; second < 10; ++second) {
    frames(60);
    expectCountsOfEveryRun();
  }
  EXPECT_EQ(captionsOf(Caption::Kind::Collisions)[1].runIndex, 1);
}

TEST_F(PresetCaption, ShowsThePresetsTextAndHidesAndShowsAgain) {
  open(stillBalls());
  EXPECT_TRUE(captionsOf(Caption::Kind::LookFor).empty());  // a scene not from a preset
  choosePreset(QStringLiteral("tunnelling"));
  std::vector<Caption> lookFor = captionsOf(Caption::Kind::LookFor);
  ASSERT_EQ(lookFor.size(), 1u);
  EXPECT_EQ(lookFor.front().text, fromView(findPreset("tunnelling")->lookFor));
  const QRect boxWithCaption = view()->transformForRun(0).boxRect();
  EXPECT_FALSE(lookFor.front().rect.intersects(boxWithCaption.adjusted(-1, -1, 1, 1)));

  // The close button hides it (and is no mouse tool press); the box takes the room.
  const int markers = markerCount(*window->charts());
  QTest::mouseClick(view(), Qt::LeftButton, {}, view()->lookForCloseButton().center());
  EXPECT_TRUE(captionsOf(Caption::Kind::LookFor).empty());
  EXPECT_FALSE(window->actions().lookFor()->isChecked());
  EXPECT_FALSE(group().interactions().pressed());
  EXPECT_EQ(markerCount(*window->charts()), markers);
  // Taller, or, where the view's width bounds the box (the charts' column beside it), as tall
  // and centred in the room the caption left.
  const QRect boxAfter = view()->transformForRun(0).boxRect();
  EXPECT_TRUE(boxAfter.height() > boxWithCaption.height() || boxAfter.top() < boxWithCaption.top())
      << "the box " << boxAfter.top() << "+" << boxAfter.height() << " against "
      << boxWithCaption.top() << "+" << boxWithCaption.height() << " with the caption";
  EXPECT_TRUE(view()->lookForCloseButton().isEmpty());

  // Hidden stays hidden on the next preset; View → What to look for shows it again.
  choosePreset(QStringLiteral("rain"));
  EXPECT_TRUE(captionsOf(Caption::Kind::LookFor).empty());
  window->actions().lookFor()->trigger();
  lookFor = captionsOf(Caption::Kind::LookFor);
  ASSERT_EQ(lookFor.size(), 1u);
  EXPECT_EQ(lookFor.front().text, fromView(findPreset("rain")->lookFor));

  // A scene from a file has none.
  window->session().loadScene(stillBalls(), QString(), QStringLiteral("still.json"));
  EXPECT_TRUE(captionsOf(Caption::Kind::LookFor).empty());
}

TEST_F(PresetCaption, TheCaptionWrapsAboveTheBoxAtEverySize) {
  open(stillBalls());
  choosePreset(QStringLiteral("mass-ratio"));
  for (const QSize size : {QSize(1000, 650), QSize(1440, 900), QSize(2560, 1440)}) {
    window->resize(size);
    QCoreApplication::processEvents();
    const QRect box = view()->transformForRun(0).boxRect().adjusted(-1, -1, 1, 1);
    const std::vector<Caption> captions = view()->captions();
    for (std::size_t i = 0; i < captions.size(); ++i) {
      EXPECT_TRUE(view()->rect().contains(captions[i].rect)) << size.width();
      EXPECT_FALSE(captions[i].rect.intersects(box)) << size.width();
      for (std::size_t j = i + 1; j < captions.size(); ++j)
        EXPECT_FALSE(captions[i].rect.intersects(captions[j].rect)) << size.width();
    }
    // The box stays the larger part of the view.
    EXPECT_GT(box.height(), view()->height() / 2) << size.width();
  }
}

TEST_F(PresetCaption, WallBoxesShowThreeWallsAndToggleOne) {
  open(stillBalls());
  choosePreset(QStringLiteral("mass-ratio"));  // no right wall
  EXPECT_TRUE(wallBox("leftWallBox")->isChecked());
  EXPECT_FALSE(wallBox("rightWallBox")->isChecked());
  EXPECT_TRUE(wallBox("bottomWallBox")->isChecked());
  EXPECT_TRUE(wallBox("topWallBox")->isChecked());

  wallBox("bottomWallBox")->click();
  EXPECT_EQ(group().world().walls, (Walls{true, false, false, true}));
  EXPECT_EQ(runs().run(0).world().walls, (Walls{true, false, false, true}));
  EXPECT_EQ(markerLabels(*window->charts()).back(), QStringLiteral("bottom wall off"));
  wallBox("rightWallBox")->click();
  EXPECT_EQ(group().world().walls, (Walls{true, true, false, true}));
  EXPECT_EQ(markerLabels(*window->charts()).back(), QStringLiteral("right wall on"));

  // Reset scene brings back the scene's own walls, and the boxes follow.
  window->session().resetScene();
  EXPECT_EQ(group().world().walls, (Walls{true, false, true, true}));
  EXPECT_FALSE(wallBox("rightWallBox")->isChecked());
  EXPECT_TRUE(wallBox("bottomWallBox")->isChecked());
}

}  // namespace
}  // namespace fooball::gui::testing
