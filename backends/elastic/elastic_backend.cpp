#include "elastic/elastic_backend.h"

#include "elastic_world.h"

namespace fooball {

namespace {

/// The seed's method done right (see ElasticWorld), behind the Backend interface: scene order and
/// options.
class ElasticBackend final : public Backend {
 public:
  ElasticBackend()
      : Backend({{"substeps", "solver substeps per step (more: less overlap, less tunnelling)", 4,
                  1, 1000, true, OptionRole::Substeps},
                 {"threads", "worker threads per step (results are identical for any count)", 1, 1,
                  64, true, OptionRole::Threads}}) {
    optionsChanged();
  }

  void load(const Scene& scene) override { world_.load(scene.balls, scene.box, scene.world); }

  void setWorld(const WorldSettings& world) override { world_.setWorld(world); }

  void step(double dt, std::span<const Vec2> forces) override { world_.step(dt, forces); }

  void setBall(std::size_t index, const BallDef& ball) override {
    world_.setBall(world_.balls().slotOf(index), ball);
  }

  std::size_t ballCount() const override { return world_.balls().size(); }

  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    const elastic::Balls& balls = world_.balls();
    for (std::size_t slot = 0; slot < balls.size(); ++slot) {
      const std::uint32_t id = balls.id[slot];
      const elastic::Ball& ball = balls.ball[slot];
      positions[id] = {ball.x, ball.y};
      velocities[id] = {ball.vx, ball.vy};
    }
  }

  BackendCounters counters() const override { return world_.counters(); }

  /// "memory_bytes": every buffer the backend holds, for the benchmarks' bytes per ball.
  std::vector<Diagnostic> diagnostics() const override {
    return {{"memory_bytes", static_cast<double>(world_.memoryBytes())}};
  }

 protected:
  void optionsChanged() override {
    world_.setSubsteps(static_cast<int>(options_.value("substeps")));
    world_.setThreads(static_cast<int>(options_.value("threads")));
  }

 private:
  elastic::ElasticWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeElasticBackend() {
  return std::make_unique<ElasticBackend>();
}

}  // namespace fooball
