// An engine's Node.js host killed (kill -9) mid-run in the app: one message that names the run,
// the engine and the signal; that run stops and the others go on; the scene is kept; nothing
// hangs and no zombie is left. The CLI's side is tests/node_host/node_host_test.cpp.

#include <signal.h>
#include <unistd.h>

#include <QCoreApplication>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "host_pool.h"
#include "test_scenes.h"

namespace fooball::gui::testing {
namespace {

/// This process's node children (the Node.js hosts of its runs, and any kept for later ones).
std::vector<pid_t> nodeChildren() {
  const std::string self = std::to_string(getpid());
  std::ifstream children("/proc/" + self + "/task/" + self + "/children");
  std::vector<pid_t> nodes;
  for (pid_t child = 0; children >> child;) {
    std::ifstream comm("/proc/" + std::to_string(child) + "/comm");
    std::string name;
    if (comm >> name && name == "node") nodes.push_back(child);
  }
  return nodes;
}

/// Kills every node child: the run's host, and kept ones, which are replaced without a word.
std::vector<pid_t> killNodeChildren() {
  const std::vector<pid_t> nodes = nodeChildren();
  for (const pid_t node : nodes)
    ::kill(node, SIGKILL);
  return nodes;
}

bool reaped(const std::vector<pid_t>& pids) {
  for (const pid_t pid : pids) {
    if (std::filesystem::exists("/proc/" + std::to_string(pid))) return false;
  }
  return true;
}

class EngineFailure : public GuiTest {
 protected:
  /// Hosts kept by earlier tests in this process would be killed too and wait unreaped in the
  /// pool: each test starts with none.
  void SetUp() override {
    node_host::HostPool::instance().clear();
    GuiTest::SetUp();
  }

  /// Frames until the failure's message has come (it is queued after the frame).
  bool framesUntilAnError() {
    return waitUntil(
        [this] {
          frames(1);
          return !errors.isEmpty();
        },
        30.0 * slowdown());
  }
};

TEST_F(EngineFailure, KillNineOfAHostMidRunStopsThatRunWithOneMessageAndTheOthersGoOn) {
  open(fooball::testing::gas(40), "elastic", {"matter"});
  frames(10);
  const double before = group().time();
  ASSERT_GT(before, 0.0);
  const std::vector<pid_t> killed = killNodeChildren();
  ASSERT_FALSE(killed.empty()) << "the matter run has no Node.js host";
  ASSERT_TRUE(framesUntilAnError()) << "no message within 30 s";

  ASSERT_EQ(errors.size(), 1) << errors.join(QLatin1Char('\n')).toStdString();
  EXPECT_TRUE(errors[0].startsWith(
      QStringLiteral("matter stopped: matter: the Node.js host was killed by signal 9")))
      << errors[0].toStdString();
  ASSERT_EQ(runs().runCount(), 1);
  EXPECT_EQ(runs().label(0), QStringLiteral("elastic"));
  EXPECT_EQ(window->charts()->runCount(), 1) << "the charts keep no curve of the stopped run";
  EXPECT_FALSE(runLegendText(*window->charts()).contains(QStringLiteral("matter")))
      << runLegendText(*window->charts()).toStdString();
  EXPECT_EQ(group().ballCount(), 40u) << "the scene is kept";
  EXPECT_FALSE(runs().paused());
  const double after = group().time();
  frames(10);
  EXPECT_GT(group().time(), after) << "the other run goes on";
  EXPECT_TRUE(reaped(killed)) << "a killed host was left a zombie";
}

TEST_F(EngineFailure, KillNineOfTheOnlyRunsHostPausesItWhereItWasAndPlayGoesOnWithANewHost) {
  open(fooball::testing::gas(40), "matter");
  frames(10);
  killNodeChildren();
  ASSERT_TRUE(framesUntilAnError());
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors[0].contains(QStringLiteral("killed by signal 9"))) << errors[0].toStdString();
  ASSERT_EQ(runs().runCount(), 1);
  EXPECT_EQ(runs().label(0), QStringLiteral("matter"));
  EXPECT_EQ(group().ballCount(), 40u);
  EXPECT_TRUE(runs().paused()) << "nothing could go on: paused where the failed step began";
  const double at = group().time();
  runs().setPaused(false);
  frames(10);
  EXPECT_GT(group().time(), at) << "play goes on with a new host";
  EXPECT_EQ(errors.size(), 1);
}

}  // namespace
}  // namespace fooball::gui::testing
