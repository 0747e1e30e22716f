// fooball-cli as users and scripts see it: run as a subprocess, judged by its exit code, its
// stdout and stderr, and the files it writes.

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "backend_profiles.h"
#include "fooball/limit_check.h"
#include "fooball/presets.h"
#include "fooball/scene_file.h"
#include "fooball/simulation.h"
#include "fooball/version.h"
#include "program_path.h"
#include "registry.h"

extern char** environ;

namespace {

using ::testing::AllOf;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;

namespace fs = std::filesystem;

struct CliResult {
  int exitCode = -1;  ///< -1 when the process did not exit normally (a signal, a sanitizer)
  std::string out;
  std::string err;
};

std::string readText(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> splitCsvRow(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream stream(row);
  for (std::string cell; std::getline(stream, cell, ',');)
    cells.push_back(cell);
  return cells;
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

/// Two balls in a 16 m × 9 m box under gravity: small enough that every run takes milliseconds.
constexpr const char* kTwoBallsScene = R"({
  "format": "fooball-scene", "version": 1, "name": "Two balls",
  "box": { "width": 16.0, "height": 9.0 },
  "gravity": [0.0, -9.81],
  "balls": [
    { "position": [2.0, 4.5], "velocity": [3.0, 0.0], "radius": 0.5 },
    { "position": [8.0, 4.5], "velocity": [-2.0, 1.0], "radius": 0.5 }
  ]
})";

/// Two balls without gravity that collide head-on-ish at t ≈ 0.2 s, far from the walls: momentum
/// and energy must come out of the collision as they went in, and a time-stepped method's
/// substeps change where the balls are afterwards.
constexpr const char* kCollidingPairScene = R"({
  "format": "fooball-scene", "version": 1, "name": "Colliding pair",
  "box": { "width": 16.0, "height": 9.0 },
  "balls": [
    { "position": [6.0, 4.5], "velocity": [3.0, 0.0], "radius": 0.5 },
    { "position": [8.0, 4.7], "velocity": [-2.0, 0.0], "radius": 0.5, "mass": 2.0 }
  ]
})";

constexpr const char* kCsvHeader =
    "time,kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y,ball_collisions,"
    "wall_collisions,wall_impulse,max_overlap,escaped";

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("fooball-cli-test-" + std::to_string(getpid()) + "-" + info->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  fs::path pathOf(const std::string& name) const { return directory_ / name; }

  fs::path writeFile(const std::string& name, const std::string& text) const {
    const fs::path path = pathOf(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  fs::path twoBallsScene() const { return writeFile("two_balls.json", kTwoBallsScene); }
  fs::path collidingPairScene() const {
    return writeFile("colliding_pair.json", kCollidingPairScene);
  }

  /// Runs fooball-cli with `arguments`, stdout and stderr captured in files of the test's
  /// directory (files, unlike pipes, cannot fill up and stall the child).
  CliResult runCli(const std::vector<std::string>& arguments) const {
    const fs::path outPath = pathOf("stdout.txt");
    const fs::path errPath = pathOf("stderr.txt");
    std::vector<std::string> words{fooball::checkout::kCliPath};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words)
      argv.push_back(word.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t child = 0;
    const int spawnError = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    CliResult result;
    if (spawnError != 0) {
      ADD_FAILURE() << "cannot start " << fooball::checkout::kCliPath << ": error " << spawnError;
      return result;
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = readText(outPath);
    result.err = readText(errPath);
    return result;
  }

  /// Expects exit code 2 and exactly one line on stderr; returns that line.
  std::string expectBadInput(const std::vector<std::string>& arguments) const {
    const CliResult result = runCli(arguments);
    EXPECT_EQ(result.exitCode, 2) << result.err;
    EXPECT_EQ(lineCount(result.err), 1u) << result.err;
    EXPECT_THAT(result.err, HasSubstr("error: "));
    EXPECT_THAT(result.out, IsEmpty());
    return result.err;
  }

 private:
  fs::path directory_;
};

TEST_F(CliTest, ShortPresetRunExitsZeroWithSummaryAndQuietStderr) {
  const CliResult result = runCli({"run", "--preset", "default", "--duration", "0.05"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, AllOf(HasSubstr("backend:"), HasSubstr("elastic"), HasSubstr("steps:"),
                                HasSubstr("energy change:"), HasSubstr("momentum change:")));
  // stderr is a file here, not a terminal: no progress line.
  EXPECT_THAT(result.err, IsEmpty());
}

TEST_F(CliTest, StepsCutShortAtAnEventCapAreAWarningAndTheDefaultIsExact) {
  // Rain settling into a pile: a few thousand events a step, far past one per ball.
  const std::vector<std::string> rain{"--preset", "rain", "--duration", "2", "--quiet"};
  std::vector<std::string> exact{"run", "--backend", "exact"};
  exact.insert(exact.end(), rain.begin(), rain.end());
  const CliResult uncapped = runCli(exact);
  EXPECT_EQ(uncapped.exitCode, 0) << uncapped.err;
  EXPECT_THAT(uncapped.err, IsEmpty());

  exact.insert(exact.end(), {"--option", "max_events_per_ball=1"});
  const CliResult capped = runCli(exact);
  EXPECT_EQ(capped.exitCode, 0) << capped.err;
  EXPECT_EQ(lineCount(capped.err), 1u) << capped.err;
  EXPECT_THAT(capped.err, ContainsRegex("^fooball-cli: warning: [0-9]+ steps were cut short"));

  std::vector<std::string> compare{"compare", "--run", "exact", "--run",
                                   "exact:max_events_per_ball=1"};
  compare.insert(compare.end(), rain.begin(), rain.end());
  const CliResult compared = runCli(compare);
  EXPECT_EQ(compared.exitCode, 0) << compared.err;
  EXPECT_EQ(lineCount(compared.err), 1u) << compared.err;
  EXPECT_THAT(compared.err,
              HasSubstr("warning: run exact:max_events_per_ball=1: " +
                        capped.err.substr(std::string("fooball-cli: warning: ").size())));
}

TEST_F(CliTest, ARunBeyondItsMethodsLimitsIsOneWarningLinePerRun) {
  // The tunnelling preset's 0.1 m shooter at 150 m/s closes 6.25 radii per default substep
  // (h = 1/240 s): beyond the 2.38 from which elastic was measured to fail (docs/accuracy.md).
  // At 32 substeps it closes 0.78, within the limit.
  const std::vector<std::string> shooter{"--preset", "tunnelling", "--duration", "0.2"};
  std::vector<std::string> run{"run", "--backend", "elastic"};
  run.insert(run.end(), shooter.begin(), shooter.end());
  const CliResult loud = runCli(run);
  EXPECT_EQ(loud.exitCode, 0) << loud.err;
  EXPECT_EQ(lineCount(loud.err), 1u) << loud.err;
  EXPECT_THAT(loud.err, ContainsRegex("^fooball-cli: warning: beyond the method's measured "
                                      "limits \\(docs/accuracy.md\\): tunnelling \\(v·h/r = "));
  EXPECT_THAT(loud.out, Not(IsEmpty()));
  // --quiet drops the summary, not the warning: as with steps cut short.
  run.push_back("--quiet");
  const CliResult quiet = runCli(run);
  EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err, loud.err);
  EXPECT_THAT(quiet.out, IsEmpty());

  // The exact solver never tunnels: no warning.
  std::vector<std::string> exact{"run", "--backend", "exact", "--quiet"};
  exact.insert(exact.end(), shooter.begin(), shooter.end());
  const CliResult exactResult = runCli(exact);
  EXPECT_EQ(exactResult.exitCode, 0) << exactResult.err;
  EXPECT_THAT(exactResult.err, IsEmpty());

  // One line per run beyond a limit, naming it; none for the run within every limit.
  std::vector<std::string> compare{
      "compare", "--run", "elastic", "--run", "exact", "--run", "elastic:substeps=32", "--quiet"};
  compare.insert(compare.end(), shooter.begin(), shooter.end());
  const CliResult compared = runCli(compare);
  EXPECT_EQ(compared.exitCode, 0) << compared.err;
  EXPECT_EQ(lineCount(compared.err), 1u) << compared.err;
  EXPECT_THAT(compared.err,
              HasSubstr("warning: run elastic: " +
                        loud.err.substr(std::string("fooball-cli: warning: ").size())));
}

TEST_F(CliTest, SummaryReportsStepsDtAndChangedOptions) {
  const CliResult result = runCli({"run", "--scene", twoBallsScene().string(), "--duration", "0.5",
                                   "--dt", "0.01", "--substeps", "3"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, AllOf(HasSubstr("Two balls"), HasSubstr("substeps=3"),
                                HasSubstr("balls:"), HasSubstr("dt:"), HasSubstr("0.01 s")));
  EXPECT_THAT(result.out, ContainsRegex("steps: +50\n"));
}

TEST_F(CliTest, ListNamesEveryBackendEveryPresetAndTheSubstepsOption) {
  const CliResult result = runCli({"list"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    EXPECT_THAT(result.out, HasSubstr(std::string(backend.name)));
  }
  ASSERT_FALSE(fooball::presets().empty());
  for (const fooball::Preset& preset : fooball::presets()) {
    EXPECT_THAT(result.out, HasSubstr(std::string(preset.name)));
  }
  EXPECT_THAT(result.out, AllOf(HasSubstr("substeps"), HasSubstr("default ")));
}

TEST_F(CliTest, HelpExitsZeroAndDescribesRun) {
  const CliResult result = runCli({"run", "--help"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, AllOf(HasSubstr("--duration"), HasSubstr("--metrics")));
}

TEST_F(CliTest, VersionPrintsTheProjectVersionAndExitsZero) {
  const CliResult result = runCli({"--version"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(result.out, std::string(fooball::kVersionLine) + "\n");
  EXPECT_THAT(std::string(fooball::kVersionLine),
              ::testing::MatchesRegex("fooball [0-9]+\\.[0-9]+\\.[0-9]+"));
}

TEST_F(CliTest, AnUnknownCommandIsNamedWithTheKnownOnes) {
  const std::string message = expectBadInput({"frobnicate", "--preset", "gas"});
  EXPECT_THAT(message, AllOf(HasSubstr("unknown command 'frobnicate'"), HasSubstr("compare"),
                             HasSubstr("failure-map")));
}

TEST_F(CliTest, MissingSubcommandExitsTwo) {
  expectBadInput({});
}

TEST_F(CliTest, UnknownFlagExitsTwoWithOneLineNamingIt) {
  EXPECT_THAT(expectBadInput({"run", "--bogus-flag"}), HasSubstr("--bogus-flag"));
}

TEST_F(CliTest, MissingFlagValueExitsTwo) {
  EXPECT_THAT(expectBadInput({"run", "--duration"}), HasSubstr("--duration"));
}

TEST_F(CliTest, UnknownBackendExitsTwoNamingItAndTheKnownBackends) {
  const std::string error = expectBadInput({"run", "--backend", "warp-drive"});
  EXPECT_THAT(error, HasSubstr("warp-drive"));
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    EXPECT_THAT(error, HasSubstr(std::string(backend.name)));
  }
}

TEST_F(CliTest, UnknownPresetExitsTwoNamingIt) {
  EXPECT_THAT(expectBadInput({"run", "--preset", "no-such-preset"}),
              AllOf(HasSubstr("no-such-preset"), HasSubstr(std::string(fooball::kDefaultPreset))));
}

TEST_F(CliTest, SceneAndPresetTogetherExitTwo) {
  EXPECT_THAT(expectBadInput({"run", "--scene", twoBallsScene().string(), "--preset", "default"}),
              AllOf(HasSubstr("--scene"), HasSubstr("--preset")));
}

TEST_F(CliTest, BrokenJsonSceneExitsTwoNamingTheFile) {
  const fs::path scene = writeFile("broken.json", "{ \"format\": \"fooball-scene\", ");
  EXPECT_THAT(expectBadInput({"run", "--scene", scene.string()}), HasSubstr("broken.json"));
}

TEST_F(CliTest, NegativeRadiusSceneExitsTwoNamingFileAndPlace) {
  std::string text = kTwoBallsScene;
  const std::string radius = "\"radius\": 0.5 }";
  text.replace(text.find(radius), radius.size(), "\"radius\": -1 }");
  const fs::path scene = writeFile("negative_radius.json", text);
  EXPECT_THAT(expectBadInput({"run", "--scene", scene.string()}),
              AllOf(HasSubstr("negative_radius.json"), HasSubstr("balls[0].radius")));
}

TEST_F(CliTest, MoreBallsThanTheLimitExitTwoNamingIt) {
  const std::string limit = std::to_string(fooball::kMaxBalls);
  const std::string count = std::to_string(fooball::kMaxBalls + 1);
  const fs::path scene =
      writeFile("too_many.json",
                R"({"format": "fooball-scene", "version": 1, "box": {"width": 16, "height": 9},
    "random_balls": {"count": )" +
                    count + R"(, "radius": [0.001, 0.001], "speed": [0, 1],
    "density": 1, "seed": 1}})");
  EXPECT_THAT(expectBadInput({"run", "--scene", scene.string(), "--duration", "0"}),
              AllOf(HasSubstr("random_balls.count"), HasSubstr("at most " + limit)));
}

TEST_F(CliTest, MissingSceneFileExitsTwoNamingIt) {
  EXPECT_THAT(expectBadInput({"run", "--scene", pathOf("absent.json").string()}),
              HasSubstr("absent.json"));
}

TEST_F(CliTest, UnknownBackendOptionExitsTwoNamingIt) {
  EXPECT_THAT(expectBadInput({"run", "--option", "warp_factor=9"}),
              AllOf(HasSubstr("warp_factor"), HasSubstr("elastic")));
}

TEST_F(CliTest, OutOfRangeBackendOptionExitsTwo) {
  for (const char* assignment : {"substeps=-1", "substeps=1e12", "substeps=many", "substeps"}) {
    SCOPED_TRACE(assignment);
    EXPECT_THAT(expectBadInput({"run", "--option", assignment}), HasSubstr("substeps"));
  }
}

TEST_F(CliTest, NonPositiveOrNonFiniteDurationAndDtExitTwo) {
  // --duration 0 is no error: it steps nothing (DurationZeroStepsNothing...).
  for (const char* flag : {"--duration", "--dt"}) {
    for (const char* value : {"-1", "nan", "inf", "-0.01", "1e999", "ten"}) {
      SCOPED_TRACE(std::string(flag) + " " + value);
      EXPECT_THAT(expectBadInput({"run", flag, value}), HasSubstr(flag));
    }
  }
  EXPECT_THAT(expectBadInput({"run", "--dt", "0"}), HasSubstr("--dt"));
}

TEST_F(CliTest, DurationShorterThanHalfAStepExitsTwo) {
  EXPECT_THAT(expectBadInput({"run", "--duration", "0.001", "--dt", "0.01"}),
              HasSubstr("--duration"));
}

TEST_F(CliTest, MoreStepsThanTheLimitExitTwo) {
  EXPECT_THAT(expectBadInput({"run", "--duration", "1e6", "--dt", "1e-6"}), HasSubstr("limit"));
}

TEST_F(CliTest, EveryBelowOneExitsTwo) {
  for (const char* every : {"0", "-3"}) {
    SCOPED_TRACE(every);
    EXPECT_THAT(expectBadInput({"run", "--every", every}), HasSubstr("--every"));
  }
}

TEST_F(CliTest, SubstepsOnBackendWithoutSubstepsExitsTwoNamingTheBackend) {
  int checked = 0;
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    if (backend.create()->options().has("substeps")) continue;
    const std::string name(backend.name);
    SCOPED_TRACE(name);
    EXPECT_THAT(expectBadInput({"run", "--backend", name, "--substeps", "2"}),
                AllOf(HasSubstr(name), HasSubstr("substeps")));
    ++checked;
  }
  // The check needs a registered backend without substeps; if every one gets them, this test
  // must find another way to reach the error rather than pass on nothing.
  EXPECT_GT(checked, 0) << "no registered backend lacks a substeps option";
}

TEST_F(CliTest, UnwritableMetricsFileExitsTwoNamingIt) {
  const std::string path = pathOf("no-such-directory/metrics.csv").string();
  EXPECT_THAT(expectBadInput({"run", "--duration", "0.05", "--metrics", path}),
              HasSubstr("no-such-directory/metrics.csv"));
}

TEST_F(CliTest, UnwritableSaveFileExitsTwoBeforeRunning) {
  const std::string path = pathOf("no-such-directory/state.json").string();
  EXPECT_THAT(expectBadInput({"run", "--duration", "0.05", "--save", path}),
              HasSubstr("no-such-directory"));
}

TEST_F(CliTest, MetricsCsvHasExactHeaderAndFirstEveryNthAndLastRows) {
  struct Case {
    const char* every;
    std::vector<double> times;  ///< s, of the rows: step 0, every N-th step, the last step
  };
  // 10 steps of 0.01 s.
  for (const Case& test :
       {Case{"3", {0.0, 0.03, 0.06, 0.09, 0.1}}, Case{"5", {0.0, 0.05, 0.1}},
        Case{"1", {0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.1}},
        Case{"25", {0.0, 0.1}}}) {
    SCOPED_TRACE(std::string("--every ") + test.every);
    const fs::path csv = pathOf("metrics.csv");
    const CliResult result =
        runCli({"run", "--scene", twoBallsScene().string(), "--duration", "0.1", "--dt", "0.01",
                "--every", test.every, "--metrics", csv.string(), "--quiet"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::vector<std::string> lines = splitLines(readText(csv));
    ASSERT_EQ(lines.size(), test.times.size() + 1);
    EXPECT_EQ(lines[0], kCsvHeader);
    for (std::size_t row = 0; row < test.times.size(); ++row) {
      const std::vector<std::string> cells = splitCsvRow(lines[row + 1]);
      ASSERT_EQ(cells.size(), 11u) << lines[row + 1];
      EXPECT_NEAR(std::stod(cells[0]), test.times[row], 1e-12);
      // total_energy is the sum of the two energy columns.
      EXPECT_DOUBLE_EQ(std::stod(cells[3]), std::stod(cells[1]) + std::stod(cells[2]));
    }
  }
}

TEST_F(CliTest, MetricsCsvWritesDoublesWithRoundTripPrecision) {
  const fs::path csv = pathOf("metrics.csv");
  const CliResult result = runCli({"run", "--scene", twoBallsScene().string(), "--duration", "0.1",
                                   "--dt", "0.01", "--metrics", csv.string(), "--quiet"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> start = splitCsvRow(splitLines(readText(csv)).at(1));
  // Σ ½ m v² for m = π·0.25 kg, v² = 9 and 5 m²/s², summed in scene order.
  const double mass = fooball::diskMass(0.5);
  const double kineticEnergy = 0.5 * mass * 9.0 + 0.5 * mass * 5.0;
  EXPECT_EQ(std::stod(start.at(1)), kineticEnergy);
}

TEST_F(CliTest, SavedStateLoadsBackBitForBit) {
  const fs::path saved = pathOf("saved.json");
  const fs::path firstCsv = pathOf("first.csv");
  ASSERT_EQ(runCli({"run", "--scene", twoBallsScene().string(), "--duration", "0.7", "--dt", "0.01",
                    "--save", saved.string(), "--metrics", firstCsv.string(), "--quiet"})
                .exitCode,
            0);
  const fooball::Scene scene = fooball::loadSceneFile(saved);
  ASSERT_EQ(scene.balls.size(), 2u);
  EXPECT_EQ(scene.name, "Two balls");
  EXPECT_NE(scene.balls[0].position, (fooball::Vec2{2.0, 4.5}));  // it did move

  // The saved file's state, as the CLI measures it on load, is the state the first run ended
  // in: energies and momentum agree to the last bit.
  const fs::path secondCsv = pathOf("second.csv");
  const CliResult second = runCli({"run", "--scene", saved.string(), "--duration", "0.01", "--dt",
                                   "0.01", "--metrics", secondCsv.string(), "--quiet"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  const std::vector<std::string> endOfFirst = splitCsvRow(splitLines(readText(firstCsv)).back());
  const std::vector<std::string> startOfSecond = splitCsvRow(splitLines(readText(secondCsv)).at(1));
  for (std::size_t column = 1; column <= 5; ++column) {
    SCOPED_TRACE(column);
    EXPECT_EQ(startOfSecond.at(column), endOfFirst.at(column));
  }
}

TEST_F(CliTest, RunningSavedHalfwayStateReproducesTheUninterruptedRun) {
  const fs::path scene = twoBallsScene();
  const fs::path halfway = pathOf("halfway.json");
  const fs::path resumed = pathOf("resumed.json");
  const fs::path straight = pathOf("straight.json");
  const auto run = [&](const fs::path& from, const char* duration, const fs::path& to) {
    const CliResult result = runCli({"run", "--scene", from.string(), "--duration", duration,
                                     "--dt", "0.01", "--save", to.string(), "--quiet"});
    EXPECT_EQ(result.exitCode, 0) << result.err;
  };
  run(scene, "0.4", halfway);
  run(halfway, "0.4", resumed);
  run(scene, "0.8", straight);

  const fooball::Scene resumedScene = fooball::loadSceneFile(resumed);
  const fooball::Scene straightScene = fooball::loadSceneFile(straight);
  ASSERT_EQ(resumedScene.balls.size(), straightScene.balls.size());
  for (std::size_t i = 0; i < straightScene.balls.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(resumedScene.balls[i].position, straightScene.balls[i].position);
    EXPECT_EQ(resumedScene.balls[i].velocity, straightScene.balls[i].velocity);
  }
}

TEST_F(CliTest, QuietPrintsNothingOnStdout) {
  const CliResult result =
      runCli({"run", "--scene", twoBallsScene().string(), "--duration", "0.1", "--quiet"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, IsEmpty());
  EXPECT_THAT(result.err, IsEmpty());
}

TEST_F(CliTest, QuietPrintsNothingWithAnyBackend) {
  // A backend's library must not write to the CLI's streams: Debian's Chipmunk prints a banner
  // on stdout when a process creates its first space (backends/chipmunk/chipmunk_banner.h). A
  // scene without gravity, so that no backend's measured limits are crossed and the CLI itself
  // has no warning to print (Bullet's pile fails from g = 1 m/s²,
  // backends/bullet/bullet_backend.h).
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    const std::string name(backend.name);
    SCOPED_TRACE(name);
    const CliResult result = runCli({"run", "--scene", collidingPairScene().string(), "--backend",
                                     name, "--duration", "0.05", "--quiet"});
    EXPECT_EQ(result.exitCode, 0) << result.err;
    EXPECT_THAT(result.out, IsEmpty());
    EXPECT_THAT(result.err, IsEmpty());
  }
}

/// The number on the summary line that starts with `label` ("energy change:"), or NaN when there
/// is no such line.
double summaryNumber(const std::string& summary, const std::string& label) {
  for (const std::string& line : splitLines(summary)) {
    if (line.rfind(label, 0) != 0) continue;
    std::istringstream value(line.substr(label.size()));
    double number = std::nan("");
    value >> number;
    return number;
  }
  return std::nan("");
}

TEST_F(CliTest, RunSummarysEnergyErrorIsTheLimitChecksNumberForTheSameRun) {
  // One definition (relativeEnergyError): `run`'s summary and the limit check, which warns from
  // it, read the same number off the same run. xpbd does not keep a gas's energy exactly (here
  // +0.16% in 2 s), so the number is not 0.
  const CliResult result =
      runCli({"run", "--preset", "gas", "--backend", "xpbd", "--duration", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  fooball::Simulation run(fooball::loadPreset("gas"), fooball::createBackend("xpbd"));
  run.run(2.0);
  const double limitChecks = fooball::measureLimitNumbers(run).relativeEnergyError;
  ASSERT_GT(std::abs(limitChecks), 1e-6) << "xpbd's gas changes its energy";
  // Printed to 6 significant digits.
  EXPECT_NEAR(summaryNumber(result.out, "energy error:"), limitChecks, 1e-5 * std::abs(limitChecks))
      << result.out;
}

TEST_F(CliTest, EveryBackendRunsACollisionAndKeepsMomentumAndEnergy) {
  // One ball–ball collision and no walls, no gravity: momentum is conserved exactly by the
  // physics and energy by restitution 1, so what the metrics show is the backend's own error,
  // bounded by its profile (tests/backend_profiles.cpp): its conformance tolerances (momentum
  // relative to Σ m|v|, energy relative to E) and its robustness overlap bound. The summary it
  // prints must say what the metrics file says.
  const fs::path scene = collidingPairScene();
  const double speedMomentum = fooball::diskMass(0.5) * 3.0 + 2.0 * 2.0;  // Σ m|v|, N·s
  constexpr double kDt = 0.01;                                            // s
  constexpr int kSteps = 50;
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    const std::string name(backend.name);
    SCOPED_TRACE(name);
    const fooball::testing::BackendProfile& profile = fooball::testing::profileFor(name);
    const fooball::testing::ConformanceTolerances& tolerances = profile.conformance;
    const fs::path csv = pathOf("metrics-" + name + ".csv");
    const CliResult result =
        runCli({"run", "--scene", scene.string(), "--backend", name, "--duration", "0.5", "--dt",
                "0.01", "--metrics", csv.string()});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_THAT(result.out, ContainsRegex("backend: +" + name + "\n"));
    const std::vector<std::string> lines = splitLines(readText(csv));
    ASSERT_EQ(lines.size(), kSteps + 2u);  // the header, the start and 50 steps
    ASSERT_EQ(lines[0], kCsvHeader);
    const std::vector<std::string> start = splitCsvRow(lines[1]);
    ASSERT_EQ(start.size(), 11u);
    const double startEnergy = std::stod(start[3]);
    std::uint64_t collisions = 0;
    for (std::size_t row = 1; row < lines.size(); ++row) {
      const std::vector<std::string> cells = splitCsvRow(lines[row]);
      ASSERT_EQ(cells.size(), 11u) << lines[row];
      // Every row: its time, the energy and momentum kept, counters that only grow, overlaps
      // within the backend's bound, nobody escaped.
      EXPECT_NEAR(std::stod(cells[0]), static_cast<double>(row - 1) * kDt, 1e-12) << lines[row];
      EXPECT_NEAR(std::stod(cells[3]), startEnergy, tolerances.energy * startEnergy) << lines[row];
      for (const std::size_t column : {4u, 5u}) {
        EXPECT_NEAR(std::stod(cells[column]), std::stod(start[column]),
                    tolerances.momentum * speedMomentum)
            << "momentum column " << column << ": " << lines[row];
      }
      EXPECT_GE(std::stoull(cells[6]), collisions) << lines[row];
      collisions = std::stoull(cells[6]);
      EXPECT_EQ(cells[7], "0") << "no wall is reached: " << lines[row];
      EXPECT_LE(std::stod(cells[9]), profile.robustness.ballOverlap) << lines[row];
      EXPECT_EQ(cells[10], "0") << "no ball escaped: " << lines[row];
    }
    EXPECT_EQ(collisions, 1u) << "the balls collide once";
    // The summary: the steps, the counters and the changes of the last row against the first.
    const std::vector<std::string> end = splitCsvRow(lines.back());
    const double endEnergy = std::stod(end[3]);
    ASSERT_TRUE(std::isfinite(endEnergy));
    EXPECT_EQ(summaryNumber(result.out, "steps:"), kSteps) << result.out;
    EXPECT_EQ(summaryNumber(result.out, "ball collisions:"), 1.0) << result.out;
    EXPECT_EQ(summaryNumber(result.out, "wall collisions:"), 0.0) << result.out;
    // Printed to 6 significant digits.
    const double energyChange = (endEnergy - startEnergy) / startEnergy;
    EXPECT_NEAR(summaryNumber(result.out, "energy change:"), energyChange,
                1e-5 * std::abs(energyChange))
        << result.out;
    EXPECT_LE(std::abs(energyChange), tolerances.energy);
    EXPECT_NEAR(summaryNumber(result.out, "energy residual:"), endEnergy - startEnergy,
                1e-5 * std::abs(endEnergy - startEnergy))
        << result.out;
    const double momentumChange = std::hypot(std::stod(end[4]) - std::stod(start[4]),
                                             std::stod(end[5]) - std::stod(start[5])) /
                                  speedMomentum;
    EXPECT_NEAR(summaryNumber(result.out, "momentum change:"), momentumChange,
                1e-5 * momentumChange)
        << result.out;
    EXPECT_LE(momentumChange, tolerances.momentum);
  }
}

// --- compare ------------------------------------------------------------------------------------

constexpr const char* kCompareHeader =
    "time,run,kinetic_energy,total_energy,momentum_x,momentum_y,energy_residual,"
    "rms_position_difference,max_position_difference";

/// The name of the first registered backend with a substeps option: `compare` runs it twice.
std::string backendWithSubsteps() {
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    if (backend.create()->options().has("substeps")) return std::string(backend.name);
  }
  return {};
}

/// The CSV's rows (without the header), each split into cells.
std::vector<std::vector<std::string>> csvRows(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  const std::vector<std::string> lines = splitLines(readText(path));
  for (std::size_t i = 1; i < lines.size(); ++i)
    rows.push_back(splitCsvRow(lines[i]));
  return rows;
}

TEST_F(CliTest, CompareWritesOneRowPerRunPerSampleWithRunZerosDifferencesZero) {
  const std::string name = backendWithSubsteps();
  ASSERT_FALSE(name.empty()) << "no registered backend has substeps";
  const std::vector<std::string> runs = {name, name + ":substeps=1"};
  const fs::path csv = pathOf("compare.csv");
  // 50 steps of 0.01 s, a row every 20: samples at 0, 0.2, 0.4 and the last, 0.5 s.
  const CliResult result = runCli({"compare", "--scene", collidingPairScene().string(), "--run",
                                   runs[0], "--run", runs[1], "--duration", "0.5", "--dt", "0.01",
                                   "--every", "20", "--csv", csv.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.err, IsEmpty()) << "not a terminal: no progress line";
  EXPECT_EQ(splitLines(readText(csv)).at(0), kCompareHeader);
  const std::vector<std::vector<std::string>> rows = csvRows(csv);
  const std::vector<double> times = {0.0, 0.2, 0.4, 0.5};
  ASSERT_EQ(rows.size(), times.size() * runs.size());
  for (std::size_t row = 0; row < rows.size(); ++row) {
    SCOPED_TRACE("row " + std::to_string(row + 1));
    const std::vector<std::string>& cells = rows[row];
    ASSERT_EQ(cells.size(), 9u);
    EXPECT_NEAR(std::stod(cells[0]), times[row / runs.size()], 1e-12);
    EXPECT_EQ(cells[1], runs[row % runs.size()]) << "runs in --run order, labelled by spec";
    for (std::size_t column = 2; column < 9; ++column)
      EXPECT_TRUE(std::isfinite(std::stod(cells[column]))) << "column " << column;
    if (row % runs.size() == 0) {
      EXPECT_EQ(cells[7], "0") << "run 0 is the reference";
      EXPECT_EQ(cells[8], "0");
    }
  }
  // Both start from the same state; after the collision one substep per step puts the balls
  // elsewhere than four do.
  EXPECT_EQ(rows[1][7], "0");
  EXPECT_EQ(rows[1][2], rows[0][2]);
  const std::vector<std::string>& last = rows.back();
  EXPECT_GT(std::stod(last[7]), 1e-6) << "the options made a difference";
  EXPECT_GE(std::stod(last[8]), std::stod(last[7])) << "largest ≥ RMS";

  EXPECT_THAT(result.out,
              AllOf(HasSubstr("Colliding pair"), HasSubstr(runs[0]), HasSubstr(runs[1]),
                    HasSubstr("steps/s"), HasSubstr("energy change"), HasSubstr("momentum change"),
                    HasSubstr("RMS divergence"), HasSubstr("departs at")));
  EXPECT_THAT(result.out, Not(HasSubstr("baseline:")));
}

TEST_F(CliTest, CompareBaselineAddsRowsNamedBaselineStartingAtTheDisplacement) {
  const std::string name(fooball::registeredBackends().front().name);
  const fs::path csv = pathOf("compare.csv");
  const CliResult result =
      runCli({"compare", "--scene", twoBallsScene().string(), "--run", name, "--run", name,
              "--duration", "0.1", "--dt", "0.01", "--baseline", "--csv", csv.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::vector<std::string>> rows = csvRows(csv);
  ASSERT_EQ(rows.size(), 11u * 3u);  // every step and the start, two runs and the baseline
  for (std::size_t row = 0; row < rows.size(); ++row) {
    SCOPED_TRACE("row " + std::to_string(row + 1));
    ASSERT_EQ(rows[row].size(), 9u);
    EXPECT_EQ(rows[row][1], row % 3 == 2 ? "baseline" : name);
    if (row % 3 == 1) {
      EXPECT_EQ(rows[row][7], "0") << "the same spec diverges by nothing";
    }
  }
  // The baseline starts 1e-9 m from run 0 (up to rounding of positions of a few metres) and,
  // in free flight, stays there.
  EXPECT_NEAR(std::stod(rows[2][7]), 1e-9, 1e-14);
  EXPECT_NEAR(std::stod(rows.back()[7]), 1e-9, 1e-13);
  EXPECT_THAT(result.out, AllOf(HasSubstr("baseline:"), HasSubstr("1e-09 m")));
}

TEST_F(CliTest, CompareQuotesASpecWithSeveralOptions) {
  // "NAME:A=1,B=2" holds a comma: the CSV quotes it, so every row keeps nine columns.
  for (const fooball::BackendInfo& backend : fooball::registeredBackends()) {
    const std::unique_ptr<fooball::Backend> made = backend.create();
    const auto options = made->options().specs();
    if (options.size() < 2) continue;
    const std::string name(backend.name);
    const std::string spec = name + ":" + options[0].name + "=" +
                             std::to_string(static_cast<long long>(options[0].defaultValue)) + "," +
                             options[1].name + "=" +
                             std::to_string(static_cast<long long>(options[1].defaultValue));
    SCOPED_TRACE(spec);
    const fs::path csv = pathOf("compare.csv");
    const CliResult result =
        runCli({"compare", "--scene", twoBallsScene().string(), "--run", name, "--run", spec,
                "--duration", "0.02", "--dt", "0.01", "--csv", csv.string(), "--quiet"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::vector<std::string> lines = splitLines(readText(csv));
    ASSERT_EQ(lines.size(), 7u);
    EXPECT_THAT(lines[2], HasSubstr(",\"" + spec + "\","));
    return;
  }
  ADD_FAILURE() << "no registered backend has two options to quote in one spec";
}

TEST_F(CliTest, CompareChartWritesAPng) {
  const std::string name(fooball::registeredBackends().front().name);
  const fs::path chart = pathOf("compare.png");
  const CliResult result =
      runCli({"compare", "--scene", collidingPairScene().string(), "--run", name, "--run",
              backendWithSubsteps() + ":substeps=1", "--duration", "0.5", "--dt", "0.01",
              "--baseline", "--chart", chart.string(), "--quiet"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, IsEmpty());
  EXPECT_THAT(result.err, IsEmpty());
  const std::string image = readText(chart);
  ASSERT_GT(image.size(), 1000u);
  EXPECT_EQ(image.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(CliTest, CompareNeedsTwoToEightRuns) {
  const std::string name(fooball::registeredBackends().front().name);
  EXPECT_THAT(expectBadInput({"compare", "--duration", "0.05"}), HasSubstr("--run"));
  EXPECT_THAT(expectBadInput({"compare", "--run", name, "--duration", "0.05"}),
              AllOf(HasSubstr("--run"), HasSubstr("got 1")));
  std::vector<std::string> nine = {"compare", "--duration", "0.05"};
  for (int i = 0; i < 9; ++i) {
    nine.push_back("--run");
    nine.push_back(name);
  }
  EXPECT_THAT(expectBadInput(nine), AllOf(HasSubstr("--run"), HasSubstr("got 9")));
  std::vector<std::string> eight(nine.begin(), nine.end() - 2);
  const CliResult result = runCli(eight);
  EXPECT_EQ(result.exitCode, 0) << result.err;
}

TEST_F(CliTest, CompareBadSpecExitsTwoNamingTheSpecAndTheReason) {
  const std::string name(fooball::registeredBackends().front().name);
  struct Case {
    std::string spec;
    std::string reason;
  };
  for (const Case& test :
       {Case{name + ":warp_factor=9", "warp_factor"}, Case{"warp-drive", "unknown backend"},
        Case{name + ":substeps", "KEY=VALUE"}, Case{name + ":substeps=1,substeps=2", "twice"},
        Case{backendWithSubsteps() + ":substeps=0", "substeps"}}) {
    SCOPED_TRACE(test.spec);
    EXPECT_THAT(expectBadInput({"compare", "--scene", twoBallsScene().string(), "--run", name,
                                "--run", test.spec, "--duration", "0.05"}),
                AllOf(HasSubstr("run spec '" + test.spec + "'"), HasSubstr(test.reason)));
  }
}

TEST_F(CliTest, CompareChecksItsNumbersAndSceneLikeRun) {
  const std::string name(fooball::registeredBackends().front().name);
  const std::vector<std::string> runs = {"compare", "--run", name, "--run", name};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> arguments = runs;
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return arguments;
  };
  EXPECT_THAT(expectBadInput(with({"--duration", "-1"})), HasSubstr("--duration"));
  EXPECT_THAT(expectBadInput(with({"--dt", "0"})), HasSubstr("--dt"));
  EXPECT_THAT(expectBadInput(with({"--every", "0"})), HasSubstr("--every"));
  EXPECT_THAT(expectBadInput(with({"--preset", "no-such-preset"})), HasSubstr("no-such-preset"));
  EXPECT_THAT(expectBadInput(with({"--scene", pathOf("absent.json").string()})),
              HasSubstr("absent.json"));
  EXPECT_THAT(expectBadInput(with({"--csv", pathOf("no-such-directory/x.csv").string()})),
              HasSubstr("no-such-directory"));
}

TEST_F(CliTest, CompareQuietPrintsNothing) {
  const std::string name(fooball::registeredBackends().front().name);
  const CliResult result = runCli({"compare", "--scene", twoBallsScene().string(), "--run", name,
                                   "--run", name, "--duration", "0.1", "--baseline", "--quiet"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, IsEmpty());
  EXPECT_THAT(result.err, IsEmpty());
}

TEST_F(CliTest, FailureMapWritesOneCsvRowPerScenePointAndAChart) {
  const fs::path csv = pathOf("failure-map.csv");
  const CliResult result =
      runCli({"failure-map", "--sweep", "mass-ratio", "--backend", "elastic", "--quick", "--csv",
              csv.string(), "--chart-dir", pathOf("").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("mass-ratio"));
  const std::vector<std::string> rows = splitLines(readText(csv));
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[0],
            "sweep,backend,variant,parameter_name,parameter,error_name,error,max_overlap,passed");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> cells = splitCsvRow(rows[i]);
    ASSERT_EQ(cells.size(), 9u) << rows[i];
    EXPECT_EQ(cells[0], "mass-ratio");
    EXPECT_EQ(cells[1], "elastic");
    // One elastic contact has a closed-form impulse: every mass ratio passes (docs/accuracy.md).
    EXPECT_EQ(cells[8], "pass") << rows[i];
  }
  EXPECT_GT(fs::file_size(pathOf("failure-mass-ratio.png")), 0u);
}

TEST_F(CliTest, FailureMapUnknownSweepExitsTwoNamingItAndTheKnownSweeps) {
  EXPECT_THAT(expectBadInput({"failure-map", "--sweep", "wobble"}),
              AllOf(HasSubstr("wobble"), HasSubstr("tunnelling"), HasSubstr("pile")));
}

// --- Saved states: saved_from and --duration 0 ---------------------------------------------------

TEST_F(CliTest, DurationZeroStepsNothingAndSavesTheSceneAsItWasRead) {
  const fs::path saved = pathOf("saved.json");
  const CliResult result =
      runCli({"run", "--preset", "rain", "--duration", "0", "--save", saved.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, ContainsRegex("steps: +0\n"));
  const fooball::Scene preset = fooball::loadPreset("rain");
  const fooball::Scene written = fooball::loadSceneFile(saved);
  EXPECT_FALSE(written.savedFrom.has_value()) << "nothing ran, so nothing was saved from a run";
  ASSERT_EQ(written.balls.size(), preset.balls.size());
  for (std::size_t i = 0; i < preset.balls.size(); ++i) {
    EXPECT_EQ(written.balls[i].position, preset.balls[i].position);
    EXPECT_EQ(written.balls[i].velocity, preset.balls[i].velocity);
  }
  EXPECT_EQ(fooball::writeScene(preset), readText(saved));
}

TEST_F(CliTest, SaveRecordsTheBackendEveryOptionAndTheTime) {
  const std::string name = backendWithSubsteps();
  ASSERT_FALSE(name.empty()) << "no registered backend has substeps";
  const fs::path saved = pathOf("saved.json");
  ASSERT_EQ(runCli({"run", "--scene", twoBallsScene().string(), "--backend", name, "--substeps",
                    "3", "--duration", "0.5", "--dt", "0.01", "--save", saved.string(), "--quiet"})
                .exitCode,
            0);
  const fooball::Scene scene = fooball::loadSceneFile(saved);
  ASSERT_TRUE(scene.savedFrom.has_value());
  EXPECT_EQ(scene.savedFrom->backend, name);
  EXPECT_EQ(scene.savedFrom->time, 0.5);
  const auto backend = fooball::createBackend(name);
  EXPECT_EQ(scene.savedFrom->options.size(), backend->options().specs().size());
  EXPECT_EQ(scene.savedFrom->options.at("substeps"), 3.0);
}

TEST_F(CliTest, RunBackendTakesARunSpecThatSubstepsAndOptionEdit) {
  const std::string name = backendWithSubsteps();
  ASSERT_FALSE(name.empty()) << "no registered backend has substeps";
  // The substeps a run saves with, given `flags` after --backend.
  const auto savedSubsteps = [&](const std::string& spec, std::vector<std::string> flags) {
    const fs::path saved = pathOf("spec.json");
    std::vector<std::string> arguments{
        "run", "--scene", twoBallsScene().string(), "--backend", spec, "--duration",
        "0.1", "--save",  saved.string(),           "--quiet"};
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    const CliResult result = runCli(arguments);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const fooball::Scene scene = fooball::loadSceneFile(saved);
    EXPECT_EQ(scene.savedFrom->backend, name) << "the spec's name, not the spec";
    return scene.savedFrom->options.at("substeps");
  };
  EXPECT_EQ(savedSubsteps(name + ":substeps=5", {}), 5.0);
  // The shorthand edits the spec: applied after it, the last one wins.
  EXPECT_EQ(savedSubsteps(name + ":substeps=5", {"--substeps", "3"}), 3.0);
  EXPECT_EQ(savedSubsteps(name + ":substeps=5", {"--substeps", "3", "--option", "substeps=7"}),
            7.0);
  const CliResult summary = runCli({"run", "--scene", twoBallsScene().string(), "--backend",
                                    name + ":substeps=6", "--duration", "0.1"});
  ASSERT_EQ(summary.exitCode, 0) << summary.err;
  EXPECT_THAT(summary.out, ContainsRegex("backend: +" + name + " \\(substeps=6\\)\n"));
}

TEST_F(CliTest, BadRunBackendSpecExitsTwoNamingTheFlagAndTheProblem) {
  EXPECT_THAT(expectBadInput({"run", "--backend", "elastic:substeps"}),
              AllOf(HasSubstr("--backend"), HasSubstr("elastic:substeps")));
  EXPECT_THAT(expectBadInput({"run", "--backend", "elastic:warp=1"}),
              AllOf(HasSubstr("--backend"), HasSubstr("warp")));
  EXPECT_THAT(expectBadInput({"run", "--backend", "elastic:substeps=0"}),
              AllOf(HasSubstr("--backend"), HasSubstr("substeps")));
  const std::string unknown = expectBadInput({"run", "--backend", "warp-drive:substeps=2"});
  EXPECT_THAT(unknown, AllOf(HasSubstr("warp-drive"), HasSubstr("elastic")));
}

/// Every registered backend's state of the rain preset after `seconds`, saved by `run --save`.
/// Every pair opens it and writes it back; each state steps on the next backend in the registry,
/// so every backend steps one. Every pair steps in-process in SavedStatesOnEveryBackend
/// (saved_state_test.cpp, the program's Simulation), which 81 sanitized runs here repeated.
TEST_F(CliTest, EveryBackendsSavedStateReopensOnEveryBackendAndWritesBackByteForByte) {
  const std::span<const fooball::BackendInfo> backends = fooball::registeredBackends();
  for (std::size_t index = 0; index < backends.size(); ++index) {
    const std::string name(backends[index].name);
    SCOPED_TRACE("saved from " + name);
    const fs::path saved = pathOf("rain-" + name + ".json");
    const CliResult save = runCli({"run", "--preset", "rain", "--backend", name, "--duration", "3",
                                   "--save", saved.string(), "--quiet"});
    ASSERT_EQ(save.exitCode, 0) << save.err;
    const std::string bytes = readText(saved);
    const fooball::Scene scene = fooball::loadSceneFile(saved);
    ASSERT_TRUE(scene.savedFrom.has_value());
    EXPECT_EQ(scene.savedFrom->backend, name);
    EXPECT_EQ(scene.savedFrom->time, 3.0);
    for (const fooball::BackendInfo& on : backends) {
      const std::string onName(on.name);
      SCOPED_TRACE("on " + onName);
      const fs::path again = pathOf("again-" + name + "-" + onName + ".json");
      const CliResult reopen = runCli({"run", "--scene", saved.string(), "--backend", onName,
                                       "--duration", "0", "--save", again.string(), "--quiet"});
      ASSERT_EQ(reopen.exitCode, 0) << reopen.err;
      EXPECT_LE(lineCount(reopen.err), 1u) << "at most the one warning line: " << reopen.err;
      EXPECT_EQ(readText(again), bytes) << "--duration 0 --save changed the file";
    }
    const std::string next(backends[(index + 1) % backends.size()].name);
    const CliResult run = runCli(
        {"run", "--scene", saved.string(), "--backend", next, "--duration", "0.1", "--quiet"});
    EXPECT_EQ(run.exitCode, 0) << "stepped on " << next << ": " << run.err;
  }
}

/// Two balls 12% of their radius deep, the first 20% of its radius into the floor.
constexpr const char* kPressedBalls = R"(
  "box": { "width": 16.0, "height": 9.0 },
  "balls": [
    { "position": [2.0, 0.4], "radius": 0.5 },
    { "position": [2.94, 2.0], "radius": 0.5 }, { "position": [2.0, 2.0], "radius": 0.5 }
  ]
})";

TEST_F(CliTest, SavedStateBeyondTheHandWrittenRulesRunsWithOneWarningLine) {
  const fs::path scene =
      writeFile("pressed.json", std::string(R"({"format": "fooball-scene", "version": 1,
         "saved_from": {"backend": "elastic", "options": {"substeps": 4}, "time": 12.5},)") +
                                    kPressedBalls);
  const fs::path again = pathOf("again.json");
  const CliResult result = runCli(
      {"run", "--scene", scene.string(), "--duration", "0", "--save", again.string(), "--quiet"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(result.err, "fooball-cli: warning: " + scene.string() +
                            ": saved from a running simulation: balls[0] crosses the bottom wall "
                            "by 0.1 m, 20% of its radius\n");
  const fooball::Scene written = fooball::loadSceneFile(again);
  ASSERT_TRUE(written.savedFrom.has_value());
  EXPECT_EQ(written.savedFrom->time, 12.5);
  EXPECT_EQ(written.balls.at(1).position, (fooball::Vec2{2.94, 2.0}));
  EXPECT_EQ(runCli({"run", "--scene", scene.string(), "--duration", "0.1", "--quiet"}).exitCode, 0);
}

TEST_F(CliTest, HandWrittenSceneBeyondTheRulesIsStillRefused) {
  const fs::path scene = writeFile(
      "pressed.json", std::string(R"({"format": "fooball-scene", "version": 1,)") + kPressedBalls);
  EXPECT_EQ(expectBadInput({"run", "--scene", scene.string(), "--duration", "0"}),
            "fooball-cli: error: " + scene.string() +
                ": balls[0].position: the ball crosses the bottom wall by 0.1 m, more than 5% of "
                "its radius\n");
}

}  // namespace
