#include "fooball/scene_file.h"

#include <QFile>
#include <QTemporaryDir>
#include <vector>

#include "gui_fixture.h"
#include "scene_commands.h"

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
  EXPECT_FALSE(openSceneFile(*window, path));
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
  EXPECT_FALSE(openSceneFile(*window, path));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors.front().contains(QStringLiteral("radius"))) << errors.front().toStdString();
  EXPECT_EQ(mainRun().ballCount(), 3u);
}

TEST_F(SceneFiles, MissingFileIsReported) {
  open(stillBalls());
  EXPECT_FALSE(openSceneFile(*window, directory.filePath(QStringLiteral("nothing.json"))));
  EXPECT_EQ(errors.size(), 1);
  EXPECT_EQ(mainRun().ballCount(), 3u);
}

TEST_F(SceneFiles, SavedSceneOpensAgainWithTheSameBalls) {
  open(fooball::testing::gas(25));
  frames(10);
  const QString path = directory.filePath(QStringLiteral("saved.json"));
  ASSERT_TRUE(saveSceneFile(*window, path));
  const Scene saved = mainRun().scene();
  frames(10);
  ASSERT_TRUE(openSceneFile(*window, path));
  EXPECT_TRUE(errors.isEmpty());
  EXPECT_EQ(mainRun().time(), 0.0);
  ASSERT_EQ(mainRun().ballCount(), saved.balls.size());
  for (std::size_t i = 0; i < saved.balls.size(); ++i)
    EXPECT_EQ(mainRun().positions()[i], saved.balls[i].position);
}

}  // namespace
}  // namespace fooball::gui::testing
