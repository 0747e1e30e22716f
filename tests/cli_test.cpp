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
#include <sstream>
#include <string>
#include <vector>

#include "fooball/presets.h"
#include "fooball/scene_file.h"

extern char** environ;

namespace {

using ::testing::AllOf;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

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

  /// Runs fooball-cli with `arguments`, stdout and stderr captured in files of the test's
  /// directory (files, unlike pipes, cannot fill up and stall the child).
  CliResult runCli(const std::vector<std::string>& arguments) const {
    const fs::path outPath = pathOf("stdout.txt");
    const fs::path errPath = pathOf("stderr.txt");
    std::vector<std::string> words{FOOBALL_CLI_PATH};
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
      ADD_FAILURE() << "cannot start " << FOOBALL_CLI_PATH << ": error " << spawnError;
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
  for (const char* backend : {"elastic", "box2d", "exact"}) {
    EXPECT_THAT(result.out, HasSubstr(backend));
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
  EXPECT_THAT(
      expectBadInput({"run", "--backend", "warp-drive"}),
      AllOf(HasSubstr("warp-drive"), HasSubstr("elastic"), HasSubstr("box2d"), HasSubstr("exact")));
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
  for (const char* flag : {"--duration", "--dt"}) {
    for (const char* value : {"-1", "0", "nan", "inf", "-0.01", "1e999", "ten"}) {
      SCOPED_TRACE(std::string(flag) + " " + value);
      EXPECT_THAT(expectBadInput({"run", flag, value}), HasSubstr(flag));
    }
  }
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
  EXPECT_THAT(expectBadInput({"run", "--backend", "exact", "--substeps", "2"}),
              AllOf(HasSubstr("exact"), HasSubstr("substeps")));
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

TEST_F(CliTest, EveryBackendRunsTheScene) {
  for (const char* backend : {"elastic", "box2d", "exact"}) {
    SCOPED_TRACE(backend);
    const CliResult result = runCli({"run", "--scene", twoBallsScene().string(), "--backend",
                                     backend, "--duration", "0.1", "--dt", "0.01"});
    EXPECT_EQ(result.exitCode, 0) << result.err;
    EXPECT_THAT(result.out, HasSubstr(backend));
  }
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

}  // namespace
