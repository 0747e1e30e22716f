// File → Record… and `fooball --record`: videos read back with FFmpeg's decoders.

#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QTemporaryDir>
#include <cmath>
#include <filesystem>
#include <vector>

#include "decoded_video.h"
#include "fooball_process.h"
#include "frames/frame_loop.h"
#include "gui_fixture.h"
#include "program_path.h"
#include "recording/record_dialog.h"
#include "recording/recording_session.h"
#include "window/window_actions.h"

namespace fooball::gui {
namespace {

using fooball::testing::decodeVideo;
using fooball::testing::meanAbsoluteDifference;
using testing::GuiTest;
using testing::runFooball;

std::vector<std::uint8_t> rgbOf(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
  std::vector<std::uint8_t> bytes;
  bytes.reserve(std::size_t(3 * rgb.width() * rgb.height()));
  for (int y = 0; y < rgb.height(); ++y) {
    const uchar* row = rgb.constScanLine(y);
    bytes.insert(bytes.end(), row, row + 3 * rgb.width());
  }
  return bytes;
}

/// The compare run of the issue, small and short: the gas on three methods side by side.
QStringList compareRun(const QString& video, int frames) {
  return {QStringLiteral("--preset"), QStringLiteral("gas"),          QStringLiteral("--compare"),
          QStringLiteral("box2d"),    QStringLiteral("--compare"),    QStringLiteral("chipmunk"),
          QStringLiteral("--show"),   QStringLiteral("side-by-side"), QStringLiteral("--size"),
          QStringLiteral("640x360"),  QStringLiteral("--record"),     video,
          QStringLiteral("--frames"), QString::number(frames)};
}

TEST(FooballRecording, AVideoWithoutADisplayMatchesAScreenshotAtTheSameSimulatedTime) {
  QTemporaryDir folder;
  const QString video = folder.filePath(QStringLiteral("run.mp4"));
  const auto recorded = runFooball(compareRun(video, 40));
  ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
  EXPECT_TRUE(recorded.out.startsWith(
      QStringLiteral("fooball: recorded 40 frames (0.67 s at 60 frames/s, 640x360, libx264)")))
      << recorded.out.toStdString();

  // A second run, 20 frames long, with a screenshot after its last: t = 20/60 s, which the
  // first video shows in its frame 20 (index 19). The screenshot of a --record run is the
  // picture the recorder took, before encoding.
  const QString shorter = folder.filePath(QStringLiteral("short.webm"));
  const QString still = folder.filePath(QStringLiteral("still.png"));
  QStringList arguments = compareRun(shorter, 20);
  arguments << QStringLiteral("--screenshot") << still;
  const auto shot = runFooball(arguments);
  ASSERT_EQ(shot.exitCode, 0) << shot.err.toStdString();

  const auto decoded = decodeVideo(video.toStdString(), {19, 39});
  EXPECT_EQ(decoded.decoder, "h264");
  EXPECT_EQ(decoded.width, 640);
  EXPECT_EQ(decoded.height, 360);
  EXPECT_EQ(decoded.frameCount, 40);
  EXPECT_NEAR(decoded.framesPerSecond, 60.0, 1e-9);
  EXPECT_NEAR(decoded.durationSeconds, 40.0 / 60.0, 0.5 / 60.0);
  const auto webm = decodeVideo(shorter.toStdString(), {19});
  EXPECT_EQ(webm.frameCount, 20);

  const QImage screenshot(still);
  ASSERT_EQ(screenshot.size(), QSize(640, 360));
  const std::vector<std::uint8_t> expected = rgbOf(screenshot);
  ASSERT_EQ(decoded.frames.size(), 2u);
  const double same = meanAbsoluteDifference(decoded.frames[0], expected);
  const double later = meanAbsoluteDifference(decoded.frames[1], expected);
  // The same simulated time: only the codec's loss between them. On this picture (300 balls
  // about 5 px wide in three black tiles, white text) that is 2.2 of 255 a channel at CRF 20,
  // nearly all of it at the balls' edges, where 4:2:0 halves the colour resolution and the
  // transform rounds sharp steps; 3 leaves room for another x264 build. Twenty frames later every
  // ball has moved by a few of its widths: 6.1, so the frame shown at 20/60 s is the one that
  // matches.
  EXPECT_LT(same, 3.0);
  EXPECT_GT(later, same + 2.0) << "frame 40 matches t = 20/60 s about as well as frame 20";
  // The WebM of the second run ends on the screenshot's picture too.
  ASSERT_EQ(webm.frames.size(), 1u);
  EXPECT_LT(meanAbsoluteDifference(webm.frames[0], expected), 3.0);
}

TEST(FooballRecording, AGifWithTheChartsIsTheVideoSize) {
  QTemporaryDir folder;
  const QString gif = folder.filePath(QStringLiteral("charts.gif"));
  const auto outcome = runFooball(
      {QStringLiteral("--preset"), QStringLiteral("gas"), QStringLiteral("--compare"),
       QStringLiteral("exact"), QStringLiteral("--size"), QStringLiteral("480x400"),
       QStringLiteral("--record"), gif, QStringLiteral("--fps"), QStringLiteral("25"),
       QStringLiteral("--record-charts"), QStringLiteral("--frames"), QStringLiteral("10")});
  ASSERT_EQ(outcome.exitCode, 0) << outcome.err.toStdString();
  const auto decoded = decodeVideo(gif.toStdString(), {9});
  EXPECT_EQ(decoded.decoder, "gif");
  EXPECT_EQ(decoded.width, 480);
  EXPECT_EQ(decoded.height, 400);
  EXPECT_EQ(decoded.frameCount, 10);
  EXPECT_NEAR(decoded.durationSeconds, 0.4, 0.02);
}

/// The lines of stderr that fooball wrote (Qt's offscreen platform may add its own notes).
QString fooballLines(const QString& err) {
  QString lines;
  for (const QString& line : err.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
    if (line.startsWith(QStringLiteral("fooball:"))) lines += line + QLatin1Char('\n');
  }
  return lines;
}

TEST(FooballRecording, AFileThatCannotBeWrittenIsOneLine) {
  QTemporaryDir folder;
  const QString missing = folder.filePath(QStringLiteral("no/such/folder/out.mp4"));
  const auto unwritable =
      runFooball({QStringLiteral("--record"), missing, QStringLiteral("--frames"),
                  QStringLiteral("3"), QStringLiteral("--size"), QStringLiteral("320x320")});
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_EQ(fooballLines(unwritable.err),
            QStringLiteral("fooball: error: %1: could not create the file: No "
                           "such file or directory\n")
                .arg(missing));

  // A disk that fills up: /dev/full refuses every write with ENOSPC.
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const QString full = folder.filePath(QStringLiteral("full.gif"));
  ASSERT_TRUE(QFile::link(QStringLiteral("/dev/full"), full));
  const auto diskFull =
      runFooball({QStringLiteral("--record"), full, QStringLiteral("--fps"), QStringLiteral("25"),
                  QStringLiteral("--frames"), QStringLiteral("5"), QStringLiteral("--size"),
                  QStringLiteral("320x320")});
  EXPECT_EQ(diskFull.exitCode, 1);
  const QString said = fooballLines(diskFull.err);
  EXPECT_EQ(said.count(QLatin1Char('\n')), 1) << said.toStdString();
  EXPECT_TRUE(said.startsWith(QStringLiteral("fooball: error: %1: ").arg(full)))
      << said.toStdString();
  EXPECT_TRUE(said.endsWith(QStringLiteral("(the disk is full)\n"))) << said.toStdString();

  const auto unknown = runFooball({QStringLiteral("--record"), QStringLiteral("out.avi"),
                                   QStringLiteral("--frames"), QStringLiteral("3")});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_EQ(unknown.err, QStringLiteral("fooball: error: --record: out.avi: unknown video type "
                                        "'.avi' (use .mp4, .webm or .gif)\n"));
}

TEST(FooballRecording, AnInterruptedRecordingIsAPlayableFile) {
  // Ctrl+C or a SIGTERM mid-recording: the video ends at the frame it was on, finished.
  QTemporaryDir folder;
  const QString video = folder.filePath(QStringLiteral("long.gif"));
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  QProcess process;
  process.setProcessEnvironment(environment);
  process.start(
      QString::fromUtf8(checkout::kGuiPath),
      {QStringLiteral("--preset"), QStringLiteral("gas"), QStringLiteral("--size"),
       QStringLiteral("320x320"), QStringLiteral("--record"), video, QStringLiteral("--fps"),
       QStringLiteral("25"), QStringLiteral("--frames"), QStringLiteral("100000")});
  // Frames are being written once the file has some (FFmpeg writes in blocks of 32 kB).
  ASSERT_TRUE(testing::waitUntil([&] { return QFileInfo(video).size() > 0; }, 60.0));
  process.terminate();
  ASSERT_TRUE(process.waitForFinished(60'000));
  EXPECT_EQ(process.exitStatus(), QProcess::NormalExit);
  EXPECT_EQ(process.exitCode(), 130);
  const QString out = QString::fromLocal8Bit(process.readAllStandardOutput());
  EXPECT_TRUE(out.contains(QStringLiteral("(interrupted)"))) << out.toStdString();
  const auto decoded = decodeVideo(video.toStdString());
  EXPECT_GT(decoded.frameCount, 0);
  EXPECT_LT(decoded.frameCount, 100000);
  EXPECT_EQ(decoded.width, 320);
}

class Recording : public GuiTest {
 protected:
  QTemporaryDir folder;
};

TEST_F(Recording, EveryFrameHoldsOneFrameTimesTheSpeedOfSimulatedTime) {
  open(testing::stillBalls());
  window->frames().setTimeScale(0.5);
  const double start = group().time();
  RecordingSession session(window->recordingTarget(), {folder.filePath(QStringLiteral("slow.mp4")),
                                                       RecordArea::Box, QSize(320, 180), 60});
  // 12 frames at 60 frames/s and 0.5×: 0.1 s of simulation, 6 steps of 1/60 s, however long
  // each frame takes.
  for (int i = 0; i < 12; ++i)
    ASSERT_TRUE(session.recordNextFrame());
  EXPECT_NEAR(group().time() - start, 0.1, 1e-12);
  EXPECT_EQ(session.frames(), 12);
  EXPECT_DOUBLE_EQ(session.seconds(), 0.2);
  EXPECT_EQ(session.stop(), QString());
  EXPECT_EQ(decodeVideo(session.settings().path.toStdString()).frameCount, 12);
}

TEST_F(Recording, FileRecordStartsStopsAndShowsTheLengthAndSize) {
  open(testing::stillBalls());
  RecordDialog* dialog = window->actions().openRecord();
  ASSERT_TRUE(dialog->isVisible());
  const QString path = folder.filePath(QStringLiteral("app.gif"));
  dialog->pathField()->setText(path);
  // A GIF is offered its own frame rates.
  EXPECT_EQ(dialog->rateChoice()->itemData(0).toInt(), 50);
  dialog->rateChoice()->setCurrentIndex(dialog->rateChoice()->findData(25));
  dialog->sizeChoice()->setCurrentIndex(dialog->sizeChoice()->findData(QSize(640, 360)));
  dialog->areaChoice()->setCurrentIndex(
      dialog->areaChoice()->findData(int(RecordArea::BoxAndCharts)));
  EXPECT_TRUE(dialog->sizeChoice()->itemText(0).startsWith(QStringLiteral("As shown (")));
  window->startLiveUpdates();  // the app's frame timer, which the recording takes over
  ASSERT_TRUE(dialog->start());
  ASSERT_NE(dialog->session(), nullptr);
  EXPECT_FALSE(dialog->pathField()->isEnabled());
  EXPECT_EQ(dialog->startButton()->text(), QStringLiteral("Stop"));
  // The window's own timer takes the frames, one per tick at the recording's rate.
  ASSERT_TRUE(testing::waitUntil([&] { return dialog->session()->frames() >= 8; }, 30.0));
  EXPECT_TRUE(dialog->progressLabel()->text().startsWith(QStringLiteral("Recording: ")))
      << dialog->progressLabel()->text().toStdString();
  // Paused, no frames come.
  runs().setPaused(true);
  const int paused = dialog->session()->frames();
  QTest::qWait(200);
  EXPECT_EQ(dialog->session()->frames(), paused);
  dialog->stop();
  EXPECT_EQ(dialog->session(), nullptr);
  EXPECT_TRUE(dialog->progressLabel()->text().startsWith(QStringLiteral("Saved app.gif: ")))
      << dialog->progressLabel()->text().toStdString();
  EXPECT_TRUE(window->frames().fixedFrameRate() == false);
  const auto decoded = decodeVideo(path.toStdString());
  EXPECT_EQ(decoded.frameCount, paused);
  EXPECT_EQ(decoded.width, 640);
  EXPECT_EQ(decoded.height, 360);
  EXPECT_TRUE(errors.isEmpty());
}

TEST_F(Recording, ClosingTheWindowLeavesAPlayableFile) {
  open(testing::stillBalls());
  RecordDialog* dialog = window->actions().openRecord();
  const QString path = folder.filePath(QStringLiteral("closed.mp4"));
  dialog->pathField()->setText(path);
  dialog->sizeChoice()->setCurrentIndex(dialog->sizeChoice()->findData(QSize(640, 360)));
  window->startLiveUpdates();
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(testing::waitUntil([&] { return dialog->session()->frames() >= 5; }, 30.0));
  // Gone without a close event, as when the app ends: the dialog and its recording go with the
  // window, and the file is finished on the way.
  window.reset();
  const auto decoded = decodeVideo(path.toStdString());
  EXPECT_GE(decoded.frameCount, 5);
  EXPECT_EQ(decoded.width, 640);
}

TEST_F(Recording, AnUnwritablePathIsOneErrorAndNoRecording) {
  open(testing::stillBalls());
  RecordDialog* dialog = window->actions().openRecord();
  dialog->pathField()->setText(folder.filePath(QStringLiteral("missing/out.webm")));
  EXPECT_FALSE(dialog->start());
  EXPECT_EQ(dialog->session(), nullptr);
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(
      errors.front().endsWith(QStringLiteral("could not create the file: No such file "
                                             "or directory")))
      << errors.front().toStdString();
  dialog->pathField()->setText(folder.filePath(QStringLiteral("out.avi")));
  EXPECT_FALSE(dialog->start());
  EXPECT_TRUE(errors.back().contains(QStringLiteral("unknown video type '.avi'")));
}

}  // namespace
}  // namespace fooball::gui
