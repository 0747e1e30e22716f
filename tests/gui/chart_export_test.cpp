// File → Export charts as PNG from the window: the image's caption names the scene and every
// run, so a picture pasted elsewhere still says what it shows.

#include <QImage>
#include <QTemporaryDir>

#include "gui_fixture.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

class ChartExport : public GuiTest {};

TEST_F(ChartExport, CaptionNamesTheSceneAndEveryRun) {
  open(stillBalls(), "elastic", {"exact", "box2d:substeps=8"});
  runs().setBaseline(true);
  frames(30);
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath(QStringLiteral("charts.png"));
  ASSERT_TRUE(window->actions().exportChartsPngTo(path));
  QImage image;
  ASSERT_TRUE(image.load(path));
  const QString caption = image.text(QStringLiteral("Description"));
  EXPECT_EQ(caption, window->actions().chartCaption());
  for (const QString& part :
       {QStringLiteral("test"), QStringLiteral("3 balls"), QStringLiteral("elastic (reference)"),
        QStringLiteral("exact"), QStringLiteral("box2d:substeps=8"),
        QStringLiteral("chaos baseline"), QStringLiteral("t = 0.50 s")}) {
    EXPECT_TRUE(caption.contains(part)) << caption.toStdString() << " lacks " << part.toStdString();
  }
  EXPECT_TRUE(errors.isEmpty());
}

}  // namespace
}  // namespace fooball::gui::testing
