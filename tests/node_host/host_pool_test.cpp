// The kept Node.js hosts (backends/node_host/host_pool.h): a backend made after another of its
// engine ended takes that one's host instead of starting node again, and steps exactly as a new
// host does; a kept host killed while it waited is replaced without a word; no more than
// HostPool::kMaxIdlePerEngine wait. Every engine in the host, as the registry lists them.

#include "host_pool.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "fooball/standard_scenes.h"
#include "registry.h"

namespace fooball::node_host {
namespace {

/// This process's children (Linux: /proc/PID/task/PID/children, the main thread's, which starts
/// every host here).
std::vector<pid_t> children() {
  const std::string self = std::to_string(getpid());
  std::ifstream file("/proc/" + self + "/task/" + self + "/children");
  std::vector<pid_t> found;
  for (pid_t child = 0; file >> child;)
    found.push_back(child);
  std::sort(found.begin(), found.end());
  return found;
}

/// Positions and velocities after `steps` steps of the 200-ball gas from a new backend.
std::vector<Vec2> stepped(const std::string& engine, int steps) {
  const std::unique_ptr<Backend> backend = createBackend(engine);
  const Scene scene = standardGas(200, 0.1);
  backend->load(scene);
  for (int i = 0; i < steps; ++i)
    backend->step(1.0 / 60.0, {});
  std::vector<Vec2> state(2 * scene.balls.size());
  backend->readState(std::span(state).first(scene.balls.size()),
                     std::span(state).last(scene.balls.size()));
  return state;
}

/// Ends the hosts an earlier test in this process left waiting.
void endWaitingHosts(const std::string& engine) {
  while (HostPool::instance().take(engine)) {
  }
}

std::vector<std::string> hostedEngines() {
  std::vector<std::string> engines;
  for (const BackendInfo& info : registeredBackends()) {
    if (!info.runtime.empty()) engines.emplace_back(info.name);
  }
  return engines;
}

TEST(HostPool, ANewBackendTakesTheHostOfOneThatEndedAndStepsExactlyAsANewHost) {
  ASSERT_FALSE(hostedEngines().empty());
  for (const std::string& engine : hostedEngines()) {
    SCOPED_TRACE(engine);
    endWaitingHosts(engine);
    const std::vector<pid_t> before = children();
    const std::vector<Vec2> fresh = stepped(engine, 60);  // a new host: node starts
    const std::vector<pid_t> kept = children();
    ASSERT_EQ(kept.size(), before.size() + 1) << "the ended backend's host was not kept";
    const std::vector<Vec2> reused = stepped(engine, 60);
    EXPECT_EQ(children(), kept) << "a second node was started instead of the kept one";
    EXPECT_TRUE(std::equal(fresh.begin(), fresh.end(), reused.begin(), [](Vec2 a, Vec2 b) {
      return a.x == b.x && a.y == b.y;
    })) << "a kept host stepped differently from a new one";
  }
}

TEST(HostPool, AKeptHostKilledWhileItWaitedIsReplacedWithoutAnError) {
  endWaitingHosts("matter");
  const std::vector<pid_t> before = children();
  stepped("matter", 1);
  std::vector<pid_t> kept = children();
  ASSERT_EQ(kept.size(), before.size() + 1);
  std::vector<pid_t> added;
  std::set_difference(kept.begin(), kept.end(), before.begin(), before.end(),
                      std::back_inserter(added));
  ASSERT_EQ(::kill(added.front(), SIGKILL), 0);
  EXPECT_NO_THROW(stepped("matter", 10));
  EXPECT_FALSE(std::filesystem::exists("/proc/" + std::to_string(added.front())))
      << "the killed host was not reaped: a zombie is left";
}

TEST(HostPool, NoMoreThanItsBoundWaitPerEngine) {
  endWaitingHosts("matter");
  const std::size_t before = children().size();
  {
    std::vector<std::unique_ptr<Backend>> runs;
    for (std::size_t i = 0; i < HostPool::kMaxIdlePerEngine + 2; ++i) {
      runs.push_back(createBackend("matter"));
      runs.back()->load(standardGas(10, 0.1));
    }
    EXPECT_EQ(children().size(), before + HostPool::kMaxIdlePerEngine + 2);
  }
  EXPECT_EQ(children().size(), before + HostPool::kMaxIdlePerEngine);
}

}  // namespace
}  // namespace fooball::node_host
