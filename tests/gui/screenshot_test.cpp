#include <gtest/gtest.h>

#include <QImage>
#include <QTemporaryDir>
#include <string>

#include "fooball/version.h"
#include "fooball_process.h"

namespace {

using fooball::gui::testing::kOffscreen;
using fooball::gui::testing::Outcome;
using fooball::gui::testing::runFooball;
using fooball::gui::testing::Variables;

TEST(FooballBinary, ScreenshotWritesANonEmptyImageWithoutADisplay) {
  QTemporaryDir directory;
  const QString path = directory.filePath(QStringLiteral("shot.png"));
  const Outcome outcome =
      runFooball({QStringLiteral("--preset"), QStringLiteral("default"), QStringLiteral("--frames"),
                  QStringLiteral("3"), QStringLiteral("--screenshot"), path},
                 {});
  ASSERT_EQ(outcome.exitCode, 0) << outcome.err.toStdString();
  EXPECT_TRUE(outcome.out.contains(QStringLiteral("mean frame time"))) << outcome.out.toStdString();
  const QImage image(path);
  ASSERT_FALSE(image.isNull());
  EXPECT_GE(image.width(), 800);
  EXPECT_GE(image.height(), 500);
  // Not a blank image: the black box, the sidebar and the balls differ.
  EXPECT_NE(image.pixel(image.width() / 4, image.height() / 3), image.pixel(image.width() - 5, 40));
}

TEST(FooballBinary, InteractiveRunWithoutADisplaySaysWhatToDoAndExits2) {
  const Outcome outcome = runFooball({}, {});
  EXPECT_EQ(outcome.exitCode, 2);
  EXPECT_TRUE(outcome.err.startsWith(QStringLiteral("fooball: no display found")))
      << outcome.err.toStdString();
  EXPECT_TRUE(outcome.err.contains(QStringLiteral("fooball-cli run --preset default")));
}

TEST(FooballBinary, ADisplayThatCannotBeUsedSaysWhatToDoAndExits2) {
  // A DISPLAY that no server answers (a stale forwarded X session): Qt gives up after its own
  // message, and fooball adds what to run instead. An empty QT_QPA_PLATFORM chooses nothing.
  for (const Variables& variables : {Variables{{QStringLiteral("DISPLAY"), QStringLiteral(":77")}},
                                     Variables{{QStringLiteral("QT_QPA_PLATFORM"), QString()}}}) {
    const Outcome outcome = runFooball({}, variables);
    EXPECT_EQ(outcome.exitCode, 2) << outcome.err.toStdString();
    EXPECT_TRUE(outcome.err.contains(QStringLiteral("fooball-cli run --preset default")))
        << outcome.err.toStdString();
  }
}

TEST(FooballBinary, BadArgumentsGiveOneLineAndExit2) {
  for (const QStringList& arguments :
       {QStringList{QStringLiteral("--frames"), QStringLiteral("zero")},
        QStringList{QStringLiteral("--backend"), QStringLiteral("nosuch")},
        QStringList{QStringLiteral("--bogus")},
        QStringList{QStringLiteral("--preset"), QStringLiteral("nosuch"),
                    QStringLiteral("--frames"), QStringLiteral("1")}}) {
    const Outcome outcome = runFooball(arguments, kOffscreen);
    EXPECT_EQ(outcome.exitCode, 2) << arguments.join(' ').toStdString();
    EXPECT_EQ(outcome.err.count(QLatin1Char('\n')), 1) << outcome.err.toStdString();
    EXPECT_TRUE(outcome.err.startsWith(QStringLiteral("fooball: error: ")))
        << outcome.err.toStdString();
  }
}

TEST(FooballBinary, VersionPrintsTheProjectVersionWithoutADisplay) {
  const Outcome outcome = runFooball({QStringLiteral("--version")}, {});
  EXPECT_EQ(outcome.exitCode, 0) << outcome.err.toStdString();
  EXPECT_EQ(outcome.out.toStdString(), std::string(fooball::kVersionLine) + "\n");
  EXPECT_TRUE(outcome.err.isEmpty()) << outcome.err.toStdString();
}

}  // namespace

TEST(FooballBinary, ScreenshotIsDarkThroughoutWithReadableText) {
  // The app sets its dark theme at startup: the menu bar, the sidebar and the status bar are as
  // dark as the box, not the platform's light grey, and the menu bar's text stands out.
  QTemporaryDir directory;
  const QString path = directory.filePath(QStringLiteral("dark.png"));
  const Outcome outcome =
      runFooball({QStringLiteral("--size"), QStringLiteral("1000x650"), QStringLiteral("--frames"),
                  QStringLiteral("1"), QStringLiteral("--screenshot"), path},
                 {});
  ASSERT_EQ(outcome.exitCode, 0) << outcome.err.toStdString();
  const QImage image = QImage(path).convertToFormat(QImage::Format_RGB32);
  ASSERT_EQ(image.size(), QSize(1000, 650));
  const auto meanLightness = [&](const QRect& region) {
    double sum = 0.0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
      for (int x = region.left(); x <= region.right(); ++x)
        sum += QColor(image.pixel(x, y)).lightnessF();
    }
    return sum / (region.width() * region.height());
  };
  const QRect menuBar(0, 0, 1000, 20);
  const QRect sidebar(740, 40, 250, 560);
  const QRect statusBar(0, 632, 1000, 18);
  for (const QRect& region : {menuBar, sidebar, statusBar})
    EXPECT_LT(meanLightness(region), 0.3) << region.x() << "," << region.y();
  // Some pixels of the menu bar are text far lighter than its background.
  int light = 0;
  for (int x = 0; x < 300; ++x) {
    for (int y = 2; y < 18; ++y)
      light += QColor(image.pixel(x, y)).lightnessF() > 0.75 ? 1 : 0;
  }
  EXPECT_GT(light, 50);
}
