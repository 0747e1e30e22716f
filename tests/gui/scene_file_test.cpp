#include "fooball/scene_file.h"

#include <QFile>
#include <QStatusBar>
#include <QTemporaryDir>
#include <vector>

#include "control/scene_commands.h"
#include "fooball/presets.h"
#include "gui_fixture.h"

namespace fooball::gui::testing {
namespace {

class SceneFiles : public GuiTest {
 protected:
  QString write(const QString& name, const QByteArray& text) {
    const QString path = directory.filePath(name);
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text);
    return path;
  }
  QTemporaryDir directory;
};

TEST_F(SceneFiles, BrokenSceneFileLeavesTheSceneUnchanged) {
  open(stillBalls());
  frames(3);
  const std::vector<Vec2> positions(mainRun().positions().begin(), mainRun().positions().end());
  const double time = mainRun().time();
  const QString path =
      write(QStringLiteral("broken.json"), R"({"format": "fooball-scene", "version": 1, "box": )");
  EXPECT_FALSE(window->scenes().openSceneFile(path));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.front().contains(QStringLiteral("broken.json")))
      << "the error names the file: " << errors.front().toStdString();
  ASSERT_EQ(mainRun().ballCount(), positions.size());
  EXPECT_EQ(mainRun().time(), time);
  for (std::size_t i = 0; i < positions.size(); ++i)
    EXPECT_EQ(mainRun().positions()[i], positions[i]);
}

TEST_F(SceneFiles, InvalidBallIsReportedWithItsPlace) {
  open(stillBalls());
  const QString path =
      write(QStringLiteral("negative.json"),
            R"({"format": "fooball-scene", "version": 1, "box": {"width": 4, "height": 3},
          "balls": [{"position": [1, 1], "radius": -1}]})");
  EXPECT_FALSE(window->scenes().openSceneFile(path));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.front().contains(QStringLiteral("radius"))) << errors.front().toStdString();
  EXPECT_EQ(mainRun().ballCount(), 3u);
}

TEST_F(SceneFiles, MissingFileIsReported) {
  open(stillBalls());
  EXPECT_FALSE(window->scenes().openSceneFile(directory.filePath(QStringLiteral("nothing.json"))));
  EXPECT_EQ(errors.size(), 1);
  EXPECT_EQ(mainRun().ballCount(), 3u);
}

TEST_F(SceneFiles, SavedSceneOpensAgainWithTheSameBalls) {
  open(fooball::testing::gas(25));
  frames(10);
  const QString path = directory.filePath(QStringLiteral("saved.json"));
  ASSERT_TRUE(window->scenes().saveSceneFile(path));
  const Scene saved = mainRun().scene();
  frames(10);
  ASSERT_TRUE(window->scenes().openSceneFile(path));
  EXPECT_TRUE(errors.isEmpty());
  EXPECT_EQ(mainRun().time(), 0.0);
  ASSERT_EQ(mainRun().ballCount(), saved.balls.size());
  for (std::size_t i = 0; i < saved.balls.size(); ++i)
    EXPECT_EQ(mainRun().positions()[i], saved.balls[i].position);
}

TEST_F(SceneFiles, SavedRainStateRecordsItsRunAndOpensAgainExactly) {
  open(loadPreset("rain"));
  frames(150);  // 2.5 s: a pile on the floor
  const QString path = directory.filePath(QStringLiteral("rain.json"));
  ASSERT_TRUE(window->scenes().saveSceneFile(path));
  const Scene shown = mainRun().scene();
  const double time = mainRun().time();

  const Scene file = loadSceneFile(QFile::encodeName(path).toStdString());
  ASSERT_TRUE(file.savedFrom.has_value());
  EXPECT_EQ(file.savedFrom->backend, group().spec(0).backend);
  EXPECT_EQ(file.savedFrom->time, time);
  EXPECT_EQ(file.savedFrom->options.size(), mainRun().backend().options().specs().size());
  ASSERT_EQ(file.balls.size(), shown.balls.size());
  for (std::size_t i = 0; i < shown.balls.size(); ++i) {
    EXPECT_EQ(file.balls[i].position, shown.balls[i].position);
    EXPECT_EQ(file.balls[i].velocity, shown.balls[i].velocity);
    EXPECT_EQ(file.balls[i].radius, shown.balls[i].radius);
    EXPECT_EQ(file.balls[i].mass, shown.balls[i].mass);
  }

  frames(10);
  ASSERT_TRUE(window->scenes().openSceneFile(path))
      << errors.join(QStringLiteral("\n")).toStdString();
  EXPECT_TRUE(errors.isEmpty());
  EXPECT_TRUE(window->messages().status().contains(QStringLiteral("saved from")))
      << window->messages().status().toStdString();
  ASSERT_EQ(mainRun().ballCount(), shown.balls.size());
  const Scene reopened = mainRun().scene();
  for (std::size_t i = 0; i < shown.balls.size(); ++i) {
    EXPECT_EQ(reopened.balls[i].position, shown.balls[i].position);
    EXPECT_EQ(reopened.balls[i].velocity, shown.balls[i].velocity);
  }
  frames(10);  // and it runs on
  EXPECT_GT(mainRun().time(), 0.0);
}

TEST_F(SceneFiles, SavedStateBeyondTheHandWrittenRulesOpensWithAWarningNotAnError) {
  open(stillBalls());
  const QByteArray balls = R"("box": {"width": 16, "height": 9},
      "balls": [{"position": [2, 2], "radius": 0.5}, {"position": [2.94, 2], "radius": 0.5}]})";
  const QString saved = write(QStringLiteral("saved.json"),
                              R"({"format": "fooball-scene", "version": 1,
      "saved_from": {"backend": "elastic", "options": {}, "time": 12.5}, )" +
                                  balls);
  ASSERT_TRUE(window->scenes().openSceneFile(saved));
  EXPECT_TRUE(errors.isEmpty()) << errors.join(QStringLiteral("\n")).toStdString();
  const QString status = window->messages().status();
  EXPECT_TRUE(status.contains(QStringLiteral(
      "saved.json: saved from a running simulation: balls[1] overlaps balls[0] by 12% of the "
      "smaller radius")))
      << status.toStdString();
  EXPECT_FALSE(status.contains(QLatin1Char('\n')));
  ASSERT_EQ(mainRun().ballCount(), 2u);
  EXPECT_EQ(mainRun().positions()[1], (Vec2{2.94, 2.0}));

  // The same balls written by hand are refused, and the scene stays.
  const QString handWritten =
      write(QStringLiteral("hand.json"), R"({"format": "fooball-scene", "version": 1, )" + balls);
  EXPECT_FALSE(window->scenes().openSceneFile(handWritten));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.front().contains(QStringLiteral("overlaps balls[0]")))
      << errors.front().toStdString();
  EXPECT_EQ(mainRun().positions()[1], (Vec2{2.94, 2.0}));
}

}  // namespace
}  // namespace fooball::gui::testing
