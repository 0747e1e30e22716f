#include "node_backend.h"

#include <algorithm>
#include <utility>

#include "host_files.h"
#include "host_pool.h"
#include "node_host.h"

namespace fooball {

namespace {

using node_host::HostPool;
using node_host::NodeHost;

class NodeBackend final : public Backend {
 public:
  explicit NodeBackend(const JsEngine& engine) : Backend(engine.optionSpecs()), engine_(engine) {}
  ~NodeBackend() override {
    if (host_) HostPool::instance().giveBack(std::move(host_));
  }
  NodeBackend(const NodeBackend&) = delete;
  NodeBackend& operator=(const NodeBackend&) = delete;

  void load(const Scene& scene) override {
    if (!host_) start();
    call([&](NodeHost& host) { host.load(scene); });
    stepSecondsAtLoad_ = host_->stepSeconds();
    stepsSinceLoad_ = 0.0;
  }

  void setWorld(const WorldSettings& world) override {
    if (host_) call([&](NodeHost& host) { host.setWorld(world); });
  }

  void step(double dt, std::span<const Vec2> forces) override {
    call([&](NodeHost& host) { host.step(dt, forces); });
    stepsSinceLoad_ += 1.0;
  }

  void setBall(std::size_t index, const BallDef& ball) override {
    call([&](NodeHost& host) { host.setBall(index, ball); });
  }

  std::size_t ballCount() const override { return host_ ? host_->ballCount() : 0; }

  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    if (!host_) return;
    const std::span<const double> state = host_->state();
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] = {state[4 * i], state[4 * i + 1]};
      velocities[i] = {state[4 * i + 2], state[4 * i + 3]};
    }
  }

  BackendCounters counters() const override {
    if (!host_) return {};
    const node_host::HostCounters& c = host_->counters();
    return {static_cast<std::uint64_t>(c.ballCollisions),
            static_cast<std::uint64_t>(c.wallCollisions), c.wallImpulse, c.dragLoss};
  }

  std::vector<Diagnostic> diagnostics() const override {
    if (!host_) return {};
    // The host's overhead per step, in ms: each step's round trip less the engine's own step.
    const node_host::HostCounters& c = host_->counters();
    const double steps = std::max(1.0, stepsSinceLoad_);
    return {{"engine_steps", c.engineSteps},
            {"balls_brought_back", c.ballsBroughtBack},
            {"engine_ms_per_step", 1e3 * c.stepSeconds / steps},
            {"host_overhead_ms_per_step",
             1e3 * (host_->stepSeconds() - stepSecondsAtLoad_ - c.stepSeconds) / steps}};
  }

 protected:
  void optionsChanged() override {
    if (host_) call([&](NodeHost& host) { host.setOptions(options_); });
  }

 private:
  void start() {
    failure_.clear();
    const std::string reason = node_host::unavailableReason(engine_.package);
    if (!reason.empty()) {
      throw std::runtime_error(std::string(engine_.name) + ": unavailable here: " + reason);
    }
    const std::string name(engine_.name);
    // A kept host that has ended meanwhile (killed while it waited) fails its first request
    // and is replaced by a new one, without a word: the run never used it.
    if ((host_ = HostPool::instance().take(name))) {
      try {
        host_->setOptions(options_);
        return;
      } catch (const node_host::HostError&) {
        host_.reset();
      }
    }
    const auto directory = node_host::hostDirectory();
    host_ = std::make_unique<NodeHost>(name, (*directory / "host.js").string());
    call([&](NodeHost& host) { host.setOptions(options_); });
  }

  /// Runs `request` on the host. A fault ends the host (it has killed and reaped the child) and
  /// is kept: every later call but load() throws it again, so a run that failed stays failed.
  template <typename Request>
  void call(Request&& request) {
    if (!host_) {
      throw std::runtime_error(failure_.empty() ? std::string(engine_.name) + ": no scene loaded"
                                                : failure_);
    }
    try {
      std::forward<Request>(request)(*host_);
    } catch (const node_host::HostError& error) {
      failure_ = error.what();
      host_.reset();
      throw;
    }
  }

  JsEngine engine_;
  std::unique_ptr<NodeHost> host_;
  std::string failure_;             ///< the fault that ended the last host, if one did
  double stepSecondsAtLoad_ = 0.0;  ///< s, host_->stepSeconds() at the last load()
  double stepsSinceLoad_ = 0.0;
};

}  // namespace

std::unique_ptr<Backend> makeNodeBackend(const JsEngine& engine) {
  return std::make_unique<NodeBackend>(engine);
}

}  // namespace fooball
