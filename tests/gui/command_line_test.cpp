#include "window/command_line.h"

#include <gtest/gtest.h>

#include "fooball/scene.h"

namespace fooball::gui {
namespace {

CommandLine parse(QStringList arguments) {
  arguments.prepend(QStringLiteral("fooball"));
  return parseCommandLine(arguments);
}

TEST(CommandLine, ReadsEveryOption) {
  const CommandLine line =
      parse({"--preset", "gas", "--backend", "box2d:substeps=8", "--compare", "exact", "--compare",
             "elastic:substeps=1", "--size", "1000x650", "--balls", "100000", "--frames", "200",
             "--screenshot", "/tmp/shot.png"});
  EXPECT_EQ(line.preset, QStringLiteral("gas"));
  EXPECT_EQ(line.backend, (RunSpec{"box2d", {"substeps=8"}}));
  EXPECT_EQ(line.compare, (std::vector<RunSpec>{{"exact", {}}, {"elastic", {"substeps=1"}}}));
  EXPECT_EQ(line.size, QSize(1000, 650));
  EXPECT_EQ(line.balls, 100000u);
  EXPECT_EQ(line.frames, 200);
  EXPECT_EQ(line.screenshot, QStringLiteral("/tmp/shot.png"));
  EXPECT_TRUE(line.headless());
}

TEST(CommandLine, ReadsDrawingOptionsAndAttractors) {
  const CommandLine line =
      parse({"--show", "temperature,vectors", "--show", "side-by-side,statistics", "--attractor",
             "8,4.5", "--attractor", "1.5,2"});
  EXPECT_EQ(line.show, (QStringList{"temperature", "vectors", "side-by-side", "statistics"}));
  ASSERT_EQ(line.attractors.size(), 2u);
  EXPECT_EQ(line.attractors[0], (Vec2{8.0, 4.5}));
  EXPECT_EQ(line.attractors[1], (Vec2{1.5, 2.0}));
}

TEST(CommandLine, ReadsVersionAndResetSettings) {
  EXPECT_TRUE(parse({"--version"}).version);
  EXPECT_TRUE(parse({"--reset-settings"}).resetSettings);
  const CommandLine line = parse({"--preset", "gas"});
  EXPECT_FALSE(line.version || line.resetSettings);
}

TEST(CommandLine, NoArgumentsIsAnInteractiveRun) {
  const CommandLine line = parse({});
  EXPECT_FALSE(line.headless());
  EXPECT_FALSE(line.sceneFile || line.preset || line.backend || line.size);
  EXPECT_TRUE(line.compare.empty());
}

TEST(CommandLine, MoreBallsThanTheLimitAreRefusedNamingIt) {
  const QString limit = QString::number(kMaxBalls);
  EXPECT_EQ(parse({"--balls", limit}).balls, kMaxBalls);
  try {
    parse({"--balls", QString::number(kMaxBalls + 1)});
    ADD_FAILURE() << "accepted " << kMaxBalls + 1 << " balls";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find(limit.toStdString()), std::string::npos)
        << error.what();
  }
}

TEST(CommandLine, RejectsBadArgumentsWithOneLine) {
  for (const QStringList& arguments :
       {QStringList{"--scene", "a.json", "--preset", "gas"},
        QStringList{"--frames", "0"},
        QStringList{"--frames", "ten"},
        QStringList{"--balls", "-1"},
        QStringList{"--backend", "nosuch"},
        QStringList{"--compare", "nosuch"},
        QStringList{"--backend", "elastic:nosuch=1"},
        QStringList{"--compare", "box2d:substeps=0"},
        QStringList{"--compare", "elastic:substeps"},
        QStringList{"--size", "1000"},
        QStringList{"--size", "10x10"},
        QStringList{"--size", "axb"},
        QStringList{"--compare", "elastic", "--compare", "elastic", "--compare", "elastic",
                    "--compare", "elastic", "--compare", "elastic", "--compare", "elastic",
                    "--compare", "elastic", "--compare", "elastic"},
        QStringList{"--unknown"},
        QStringList{"stray"},
        QStringList{"--frames"},
        QStringList{"--frames", "2", "--frames", "3"},
        QStringList{"--show", "sparkles"},
        QStringList{"--attractor", "1"},
        QStringList{"--attractor", "a,b"}}) {
    try {
      parse(arguments);
      ADD_FAILURE() << "accepted: " << arguments.join(' ').toStdString();
    } catch (const UsageError& error) {
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
  }
}

TEST(CommandLine, ABadRunSpecIsNamedWithTheReason) {
  try {
    parse({"--compare", "box2d:velocity_iterations=0"});
    FAIL();
  } catch (const UsageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("box2d:velocity_iterations=0"), std::string::npos) << message;
    EXPECT_NE(message.find("velocity_iterations"), std::string::npos) << message;
  }
}

TEST(CommandLine, UnknownBackendErrorListsTheKnownOnes) {
  try {
    parse({"--backend", "nosuch"});
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("elastic"), std::string::npos);
  }
}

TEST(CommandLine, ReadsARecording) {
  const CommandLine line = parse({"--preset", "gas", "--size", "640x360", "--record", "out.GIF",
                                  "--frames", "50", "--fps", "25", "--record-charts"});
  EXPECT_EQ(line.record, QStringLiteral("out.GIF"));
  EXPECT_EQ(line.recordFramesPerSecond, 25);
  EXPECT_TRUE(line.recordCharts);
  EXPECT_EQ(recordingSize(line), QSize(640, 360));
  EXPECT_TRUE(line.headless());
  // Without --size, --fps: 1280x720 at 60 frames/s.
  const CommandLine plain = parse({"--record", "a.webm", "--frames", "3"});
  EXPECT_EQ(recordingSize(plain), QSize(1280, 720));
  EXPECT_EQ(plain.recordFramesPerSecond, 60);
  EXPECT_FALSE(plain.recordCharts);
}

TEST(CommandLine, ABadRecordingIsOneLineNamingTheProblem) {
  const struct {
    QStringList arguments;
    const char* message;
  } cases[] = {
      {{"--record", "out.avi", "--frames", "10"},
       "--record: out.avi: unknown video type '.avi' (use .mp4, .webm or .gif)"},
      {{"--record", "out.mp4"}, "--record: give the video's length with --frames N"},
      {{"--record", "out.mp4", "--frames", "10", "--size", "641x360"},
       "--record: video size 641x360: MP4 (H.264) needs an even width and height"},
      {{"--record", "out.gif", "--frames", "10"},
       "--record: 60 frames/s: animated GIF plays 50, 25, 20, 10 (its frame delay is in "
       "hundredths of a second)"},
      {{"--fps", "30", "--frames", "10"}, "--fps: only with --record"},
      {{"--record-charts", "--frames", "10"}, "--record-charts: only with --record"},
      {{"--record", "a.mp4", "--frames", "10", "--fps", "0"},
       "--fps: expected a whole number from 1 to 1000 (got '0')"},
  };
  for (const auto& c : cases) {
    try {
      parse(c.arguments);
      ADD_FAILURE() << "accepted: " << c.arguments.join(' ').toStdString();
    } catch (const UsageError& error) {
      EXPECT_EQ(std::string(error.what()), c.message);
    }
  }
}

TEST(CommandLine, HelpNamesTheRecordingOptions) {
  const QString help = usageText();
  for (const char* option : {"--record FILE", "--fps N", "--record-charts"})
    EXPECT_TRUE(help.contains(QLatin1String(option))) << option;
}

}  // namespace
}  // namespace fooball::gui
