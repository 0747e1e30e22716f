// File → Export charts as PNG from the window: the image's caption names the scene and every
// run, so a picture pasted elsewhere still says what it shows.

#include <QImage>
#include <QSet>
#include <QTemporaryDir>

#include "gui_fixture.h"
#include "view/simulation_view.h"
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

TEST_F(ChartExport, ImageOfTheBoxIsTheViewAsDrawn) {
  open(stillBalls(), "elastic", {"exact"});
  frames(3);
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath(QStringLiteral("box.png"));
  ASSERT_TRUE(window->actions().saveBoxImageTo(path));
  QImage image;
  ASSERT_TRUE(image.load(path));
  const QImage drawn = view()->grab().toImage();
  EXPECT_EQ(image.size(), drawn.size());
  EXPECT_EQ(image.size(), view()->size() * view()->devicePixelRatio());
  // Not blank: the box's background, its walls and the balls are more than one colour, and the
  // pixels are the view's.
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); y += 4) {
    for (int x = 0; x < image.width(); x += 4)
      colours.insert(image.pixel(x, y));
  }
  EXPECT_GT(colours.size(), 3);
  EXPECT_EQ(image.convertToFormat(QImage::Format_RGB32),
            drawn.convertToFormat(QImage::Format_RGB32));
  EXPECT_FALSE(
      window->actions().saveBoxImageTo(directory.filePath(QStringLiteral("none/box.png"))));
  EXPECT_EQ(errors.size(), 1) << "one clear error for a file it cannot write";
}

}  // namespace
}  // namespace fooball::gui::testing
