#include "command_line.h"

#include <gtest/gtest.h>

namespace fooball::gui {
namespace {

CommandLine parse(QStringList arguments) {
  arguments.prepend(QStringLiteral("fooball"));
  return parseCommandLine(arguments);
}

TEST(CommandLine, ReadsEveryOption) {
  const CommandLine line =
      parse({"--preset", "gas", "--backend", "box2d", "--compare", "exact", "--balls", "100000",
             "--frames", "200", "--screenshot", "/tmp/shot.png"});
  EXPECT_EQ(line.preset, QStringLiteral("gas"));
  EXPECT_EQ(line.backend, QStringLiteral("box2d"));
  EXPECT_EQ(line.compare, QStringLiteral("exact"));
  EXPECT_EQ(line.balls, 100000u);
  EXPECT_EQ(line.frames, 200);
  EXPECT_EQ(line.screenshot, QStringLiteral("/tmp/shot.png"));
  EXPECT_TRUE(line.headless());
}

TEST(CommandLine, ReadsDrawingOptionsAndAttractors) {
  const CommandLine line = parse({"--show", "temperature,vectors", "--show", "side-by-side",
                                  "--attractor", "8,4.5", "--attractor", "1.5,2"});
  EXPECT_EQ(line.show, (QStringList{"temperature", "vectors", "side-by-side"}));
  ASSERT_EQ(line.attractors.size(), 2u);
  EXPECT_EQ(line.attractors[0], (Vec2{8.0, 4.5}));
  EXPECT_EQ(line.attractors[1], (Vec2{1.5, 2.0}));
}

TEST(CommandLine, NoArgumentsIsAnInteractiveRun) {
  const CommandLine line = parse({});
  EXPECT_FALSE(line.headless());
  EXPECT_FALSE(line.sceneFile || line.preset || line.backend || line.compare);
}

TEST(CommandLine, RejectsBadArgumentsWithOneLine) {
  for (const QStringList& arguments :
       {QStringList{"--scene", "a.json", "--preset", "gas"}, QStringList{"--frames", "0"},
        QStringList{"--frames", "ten"}, QStringList{"--balls", "-1"},
        QStringList{"--backend", "nosuch"}, QStringList{"--compare", "nosuch"},
        QStringList{"--unknown"}, QStringList{"stray"}, QStringList{"--frames"},
        QStringList{"--frames", "2", "--frames", "3"}, QStringList{"--show", "sparkles"},
        QStringList{"--attractor", "1"}, QStringList{"--attractor", "a,b"}}) {
    try {
      parse(arguments);
      ADD_FAILURE() << "accepted: " << arguments.join(' ').toStdString();
    } catch (const UsageError& error) {
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
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

}  // namespace
}  // namespace fooball::gui
