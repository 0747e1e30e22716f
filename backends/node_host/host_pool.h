#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "node_host.h"

namespace fooball::node_host {

/// Node.js hosts that a backend has finished with, kept running for the next backend of the same
/// engine. Starting a host costs node's start-up and the engine's load (Rapier's WebAssembly:
/// about 0.35 s of CPU, 0.5–1 s of waiting), and FooBall makes new backends often: every edit of
/// a run that has stepped (a slider, a ball, the walls) reloads it from its last anchor in a new
/// backend, and a step given up leaves its backend to finish in the background. A host loads
/// whole scenes anew (host.js), so a kept one steps exactly as a new one would. Shared by every
/// thread; at most kMaxIdlePerEngine wait per engine (a run group's runs and its baseline), and
/// the rest end.
class HostPool {
 public:
  static constexpr std::size_t kMaxIdlePerEngine = 9;

  static HostPool& instance();

  /// A waiting host of `engine`, or null if none waits.
  std::unique_ptr<NodeHost> take(const std::string& engine);
  /// Keeps `host` for the next take() of its engine, emptied of its scene first (a host that
  /// fails to empty, or one too many, ends).
  void giveBack(std::unique_ptr<NodeHost> host);
  /// Ends every kept host: for a process that must have no idle node children, such as a test
  /// that kills and counts them after other tests in the same process kept theirs.
  void clear();

 private:
  std::mutex mutex_;
  std::map<std::string, std::vector<std::unique_ptr<NodeHost>>, std::less<>> idle_;
};

}  // namespace fooball::node_host
