#include "host_pool.h"

#include <utility>

namespace fooball::node_host {

HostPool& HostPool::instance() {
  static HostPool pool;
  return pool;
}

std::unique_ptr<NodeHost> HostPool::take(const std::string& engine) {
  const std::lock_guard lock(mutex_);
  const auto found = idle_.find(engine);
  if (found == idle_.end() || found->second.empty()) return nullptr;
  std::unique_ptr<NodeHost> host = std::move(found->second.back());
  found->second.pop_back();
  return host;
}

void HostPool::giveBack(std::unique_ptr<NodeHost> host) {
  try {
    host->load(Scene{});  // frees the engine's world: a kept host holds no balls
  } catch (const HostError&) {
    return;  // it has ended (killed and reaped); nothing to keep
  }
  std::unique_ptr<NodeHost> surplus;  // ended outside the lock
  const std::lock_guard lock(mutex_);
  std::vector<std::unique_ptr<NodeHost>>& waiting = idle_[host->engine()];
  if (waiting.size() < kMaxIdlePerEngine)
    waiting.push_back(std::move(host));
  else
    surplus = std::move(host);
}

void HostPool::clear() {
  std::map<std::string, std::vector<std::unique_ptr<NodeHost>>, std::less<>> ended;  // outside
  {
    const std::lock_guard lock(mutex_);
    ended.swap(idle_);
  }
}

}  // namespace fooball::node_host
