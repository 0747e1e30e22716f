#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.h"
#include "fooball/options.h"
#include "fooball/scene.h"
#include "host_protocol.h"

namespace fooball::node_host {

/// A fault of the Node.js host: one line naming the engine, what happened and how the child's
/// stderr ends, e.g. "matter: the Node.js host was killed by signal 9 (Killed); its stderr
/// ends: …". The host is gone when this is thrown (killed and reaped).
class HostError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One `node host.js` child running one engine's adapter (backends/js/host.js), and the requests
/// backend.h needs. Each request waits for its reply at most `timeout`; a child that crashes,
/// exits, hangs past it or answers garbage is killed and reaped and the request throws HostError.
/// The buffers keep their capacity, so a step allocates nothing once they have grown.
class NodeHost {
 public:
  static constexpr std::chrono::milliseconds kDefaultTimeout{30'000};

  /// Starts node on `hostScript` and shakes hands. `engine` names the adapter
  /// (backends/js/adapters/<engine>.js). Throws HostError.
  NodeHost(std::string engine, const std::string& hostScript,
           std::chrono::milliseconds timeout = kDefaultTimeout);

  const std::string& engine() const { return engine_; }
  const std::string& nodeVersion() const { return nodeVersion_; }
  const std::string& engineVersion() const { return engineVersion_; }

  void setOptions(const OptionSet& options);
  void load(const Scene& scene);
  void setWorld(const WorldSettings& world);
  void setBall(std::size_t index, const BallDef& ball);
  /// `forces` (N) one per ball or empty.
  void step(double dt, std::span<const Vec2> forces);

  /// From the last reply: x, y, vx, vy per ball (m, m/s), and the counters.
  std::span<const double> state() const { return state_; }
  std::size_t ballCount() const { return state_.size() / 4; }
  const HostCounters& counters() const { return counters_; }
  /// s, wall-clock time of every step() since this host started: the engine's step
  /// (counters().stepSeconds, since the last load) and the host's overhead (the frames both
  /// ways through the pipes, the state's read-back in JavaScript and here).
  double stepSeconds() const { return stepSeconds_; }

  pid_t pid() const { return child_.pid(); }

 private:
  /// Sends the frame in writer_ and reads the reply into reply_; throws HostError.
  FrameKind exchange();
  /// exchange() expecting a STATE reply, which it parses into state_ and counters_.
  void exchangeForState();
  [[noreturn]] void fail(const std::string& what);

  std::string engine_;
  std::chrono::milliseconds timeout_;
  ChildProcess child_;
  FrameWriter writer_;
  std::vector<std::byte> reply_;
  std::vector<double> state_;
  HostCounters counters_;
  double stepSeconds_ = 0.0;
  std::string nodeVersion_;
  std::string engineVersion_;
};

}  // namespace fooball::node_host
