// The Node.js host with a real engine (matter.js, the lightest to start) and through fooball-cli:
// a child killed with SIGKILL mid-run stops that run with one error and is reaped; with Node.js
// or the npm packages missing, the engines are listed as unavailable with the fix and everything
// else runs.

#include "node_host.h"

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fooball/standard_scenes.h"
#include "host_files.h"
#include "program_path.h"
#include "registry.h"

extern char** environ;

namespace fooball::node_host {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// Whether process `pid` still exists (a zombie does: /proc keeps it until it is reaped).
bool processExists(pid_t pid) {
  return fs::exists("/proc/" + std::to_string(pid));
}

std::string hostScript() {
  const auto directory = hostDirectory();
  return directory ? (*directory / "host.js").string() : std::string("(no host directory)");
}

TEST(NodeHost, KilledChildMidRunIsOneErrorAndIsReaped) {
  ASSERT_EQ(unavailableReason("matter-js"), "") << "the suites need the Node.js host";
  NodeHost host("matter", hostScript());
  EXPECT_THAT(host.engineVersion(), HasSubstr("0.20.0"));
  host.load(standardGas(200, 0.1));
  host.step(1.0 / 60.0, {});
  const pid_t child = host.pid();
  ASSERT_TRUE(processExists(child));
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  try {
    for (int i = 0; i < 100; ++i)  // the first request after the kill fails
      host.step(1.0 / 60.0, {});
    ADD_FAILURE() << "a step went on after the host was killed";
  } catch (const HostError& error) {
    EXPECT_THAT(error.what(), HasSubstr("matter: the Node.js host was killed by signal 9"));
  }
  EXPECT_FALSE(processExists(child)) << "the child was not reaped: a zombie is left";
}

/// $FOOBALL_NODE_OPTIONS set for one test, and as it was after it.
class NodeOptions {
 public:
  explicit NodeOptions(const char* options) {
    if (const char* before = std::getenv(kName); before != nullptr) before_ = before;
    ::setenv(kName, options, 1);
  }
  NodeOptions(const NodeOptions&) = delete;
  NodeOptions& operator=(const NodeOptions&) = delete;
  ~NodeOptions() {
    if (before_) {
      ::setenv(kName, before_->c_str(), 1);
    } else {
      ::unsetenv(kName);
    }
  }

 private:
  static constexpr const char* kName = "FOOBALL_NODE_OPTIONS";
  std::optional<std::string> before_;
};

TEST(NodeHost, NodeGetsItsOptionsAndOneItRefusesIsOneError) {
  const NodeOptions options("--stack-size=900 --no-such-option-of-node");
  try {
    NodeHost host("matter", hostScript());
    ADD_FAILURE() << "node started with an option it does not have";
  } catch (const HostError& error) {
    EXPECT_THAT(error.what(), HasSubstr("matter: "));
    EXPECT_THAT(error.what(), HasSubstr("bad option: --no-such-option-of-node"));
  }
}

TEST(NodeHost, WebAssemblyStepsBitForBitTheSameInEitherOfV8sTiers) {
  // scripts/test starts the hosts with FOOBALL_NODE_OPTIONS=--liftoff-only (the test presets):
  // V8's baseline WebAssembly compiler alone. Its optimising tier (TurboFan) was a third of the
  // CPU of the hosts the tests start, for runs too short to repay it. WebAssembly's arithmetic
  // is defined bit for bit, so either tier must give the same run: each engine here runs once
  // with the baseline compiler only and once with the optimising one only.
  const Scene scene = standardGas(300, 0.2);
  for (const char* engine : {"rapier", "box2d3"}) {
    SCOPED_TRACE(engine);
    std::vector<double> loaded;
    std::vector<double> stepped[2];
    const char* tiers[2] = {"--liftoff-only", "--no-liftoff"};
    for (int tier = 0; tier < 2; ++tier) {
      const NodeOptions options(tiers[tier]);
      NodeHost host(engine, hostScript());
      host.setOptions(createBackend(engine)->options());
      host.load(scene);
      loaded.assign(host.state().begin(), host.state().end());
      for (int frame = 0; frame < 60; ++frame)
        host.step(1.0 / 60.0, {});
      stepped[tier].assign(host.state().begin(), host.state().end());
    }
    ASSERT_EQ(stepped[0].size(), 4 * scene.balls.size());
    EXPECT_NE(stepped[0], loaded) << "the run did not move";
    EXPECT_EQ(stepped[0], stepped[1]);
  }
}

TEST(NodeHost, StateComesBackAsLoadedAndAStepMovesIt) {
  NodeHost host("matter", hostScript());
  Scene scene = standardGas(3, 0.01);
  host.load(scene);
  ASSERT_EQ(host.ballCount(), 3u);
  // 64 px/m is a power of two: positions go to pixels and back exactly.
  EXPECT_EQ(host.state()[0], scene.balls[0].position.x);
  EXPECT_EQ(host.state()[1], scene.balls[0].position.y);
  host.step(0.5, {});
  EXPECT_NEAR(host.state()[0], scene.balls[0].position.x + 0.5 * scene.balls[0].velocity.x, 1e-12);
  EXPECT_EQ(host.counters().engineSteps, 1.0);
}

/// fooball-cli with `arguments` and `environment` (NAME=VALUE entries added to ours); stderr is
/// kept in `errors`.
class Cli {
 public:
  Cli(std::vector<std::string> arguments, std::vector<std::string> environment = {}) {
    errorsPath_ = fs::temp_directory_path() / ("fooball-node-host-cli-" + std::to_string(getpid()) +
                                               "-" + std::to_string(counter_++) + ".txt");
    std::vector<std::string> words{checkout::kCliPath};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words)
      argv.push_back(word.data());
    argv.push_back(nullptr);
    std::vector<std::string> variables = std::move(environment);
    for (char** entry = environ; *entry != nullptr; ++entry) {
      const std::string text(*entry);
      const std::string name = text.substr(0, text.find('='));
      bool replaced = false;
      for (const std::string& chosen : variables)
        replaced = replaced || chosen.starts_with(name + "=");
      if (!replaced) variables.push_back(text);
    }
    std::vector<char*> envp;
    for (std::string& variable : variables)
      envp.push_back(variable.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO,
                                     (errorsPath_.string() + ".out").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errorsPath_.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    spawned_ = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~Cli() {
    if (spawned_ && exitCode_ == kRunning) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    fs::remove(errorsPath_);
    fs::remove(errorsPath_.string() + ".out");
  }

  pid_t pid() const { return pid_; }
  bool spawned() const { return spawned_; }

  /// The exit code once it has exited, within `limit`; kRunning if it has not (or a signal ended
  /// it).
  int wait(std::chrono::milliseconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (exitCode_ == kRunning && std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exitCode_ = WIFEXITED(status) ? WEXITSTATUS(status) : kSignalled;
        break;
      }
      std::this_thread::sleep_for(10ms);
    }
    return exitCode_;
  }

  std::string errors() const { return read(errorsPath_); }
  std::string output() const { return read(errorsPath_.string() + ".out"); }

  static constexpr int kRunning = -1;
  static constexpr int kSignalled = -2;

 private:
  static std::string read(const fs::path& path) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }
  static inline int counter_ = 0;
  fs::path errorsPath_;
  pid_t pid_ = -1;
  bool spawned_ = false;
  int exitCode_ = kRunning;
};

/// The children of `pid` (Linux: /proc/PID/task/PID/children).
std::vector<pid_t> childrenOf(pid_t pid) {
  std::ifstream file("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  std::vector<pid_t> children;
  for (pid_t child = 0; file >> child;)
    children.push_back(child);
  return children;
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(NodeHostCli, KillNineOfTheHostMidRunExitsOneWithOneLineAndNothingHangs) {
  Cli cli({"run", "--preset", "dense", "--backend", "matter", "--duration", "1000", "--quiet"});
  ASSERT_TRUE(cli.spawned());
  // Wait for its node child, then let it run a little.
  std::vector<pid_t> children;
  for (int i = 0; i < 500 && children.empty(); ++i) {
    std::this_thread::sleep_for(20ms);
    children = childrenOf(cli.pid());
  }
  ASSERT_EQ(children.size(), 1u) << "fooball-cli started no Node.js host";
  std::this_thread::sleep_for(300ms);
  ASSERT_EQ(::kill(children.front(), SIGKILL), 0);
  ASSERT_EQ(cli.wait(20s), 1) << "fooball-cli did not exit 1 within 20 s: " << cli.errors();
  EXPECT_EQ(lineCount(cli.errors()), 1u) << cli.errors();
  EXPECT_THAT(cli.errors(),
              HasSubstr("error: matter: the Node.js host was killed by signal 9 (Killed)"));
}

TEST(NodeHostCli, WithoutNodeTheEnginesAreListedUnavailableWithTheFixAndTheRestRuns) {
  const std::string noNode = "PATH=" + fs::temp_directory_path().string();
  Cli list({"list"}, {noNode});
  ASSERT_EQ(list.wait(20s), 0) << list.errors();
  EXPECT_THAT(list.output(),
              HasSubstr("unavailable here: Node.js not found on PATH (fix: apt install nodejs)"));

  Cli matter({"run", "--preset", "head-on", "--backend", "matter", "--duration", "0.1"}, {noNode});
  ASSERT_EQ(matter.wait(20s), 1) << matter.errors();
  EXPECT_EQ(lineCount(matter.errors()), 1u) << matter.errors();
  EXPECT_THAT(matter.errors(), HasSubstr("matter: unavailable here: Node.js not found on PATH "
                                         "(fix: apt install nodejs)"));

  Cli elastic({"run", "--preset", "head-on", "--backend", "elastic", "--duration", "0.1"},
              {noNode});
  EXPECT_EQ(elastic.wait(20s), 0) << elastic.errors();
}

TEST(NodeHostCli, WithoutTheNpmPackagesTheFixIsNpmCi) {
  const fs::path bare =
      fs::temp_directory_path() / ("fooball-bare-host-" + std::to_string(getpid()));
  fs::create_directories(bare);
  std::ofstream(bare / "host.js")
      << "// a host directory whose npm packages were never installed\n";
  Cli list({"list"}, {"FOOBALL_NODE_HOST_DIR=" + bare.string()});
  EXPECT_EQ(list.wait(20s), 0) << list.errors();
  EXPECT_THAT(list.output(), HasSubstr("unavailable here: npm package matter-js is not installed "
                                       "(fix: npm ci in " +
                                       bare.string() + ")"));
  fs::remove_all(bare);
}

}  // namespace
}  // namespace fooball::node_host
