#include "elastic/elastic_backend.h"

#include "elastic_options.h"
#include "elastic_world.h"

namespace fooball {

namespace {

/// The seed's method done right (see ElasticWorld), behind the Backend interface: scene order and
/// options.
class ElasticBackend final : public Backend {
 public:
  ElasticBackend() : Backend(elastic::elasticOptionSpecs()) { optionsChanged(); }

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

  /// "memory_bytes": every buffer the backend holds, for the benchmarks' bytes per ball;
  /// "workers": the threads that share each step (`threads` and `balls_per_thread`).
  std::vector<Diagnostic> diagnostics() const override {
    return {{"memory_bytes", static_cast<double>(world_.memoryBytes())},
            {"workers", static_cast<double>(world_.workers())}};
  }

 protected:
  void optionsChanged() override {
    const elastic::ElasticSettings settings = elastic::readElasticSettings(options_);
    world_.setSubsteps(settings.substeps);
    world_.setWorkerPolicy({settings.threads, settings.ballsPerThread});
  }

 private:
  elastic::ElasticWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeElasticBackend() {
  return std::make_unique<ElasticBackend>();
}

}  // namespace fooball
