#include "elastic/elastic_backend.h"

#include "elastic_world.h"

namespace fooball {

namespace {

/// Balls each worker beyond the first needs before it joins a step. A worker adds a barrier wait
/// to every phase of a substep: ~15 µs on an idle two-core machine, but up to a scheduler time
/// slice when another process holds the other core, so beside two busy processes two workers
/// on the 38-ball default scene take 11.8 ms a step against 0.9 µs for one. At 600'000 balls
/// (two workers) they are 1.1–1.8× faster than one, idle or busy, and at 300'000 (one worker)
/// this gives up the 2.1× that two would gain on an idle machine (docs/performance.md).
constexpr double kBallsPerThread = 250'000;

/// The seed's method done right (see ElasticWorld), behind the Backend interface: scene order and
/// options.
class ElasticBackend final : public Backend {
 public:
  ElasticBackend()
      : Backend(
            {{"substeps", "solver substeps per step (more: less overlap, less tunnelling)", 4, 1,
              1000, true, OptionRole::Substeps},
             {"threads", "worker threads per step, at most (results are identical for any count)",
              1, 1, 64, true, OptionRole::Threads},
             {"balls_per_thread",
              "balls each worker thread needs before it joins a step (0: every thread, always)",
              kBallsPerThread, 0, 1e9, true, OptionRole::BallsPerThread}}) {
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

  /// "memory_bytes": every buffer the backend holds, for the benchmarks' bytes per ball;
  /// "workers": the threads that share each step (`threads` and `balls_per_thread`).
  std::vector<Diagnostic> diagnostics() const override {
    return {{"memory_bytes", static_cast<double>(world_.memoryBytes())},
            {"workers", static_cast<double>(world_.workers())}};
  }

 protected:
  void optionsChanged() override {
    world_.setSubsteps(static_cast<int>(options_.value("substeps")));
    world_.setWorkerPolicy({static_cast<int>(options_.value("threads")),
                            static_cast<std::size_t>(options_.value("balls_per_thread"))});
  }

 private:
  elastic::ElasticWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeElasticBackend() {
  return std::make_unique<ElasticBackend>();
}

}  // namespace fooball
