#include "xpbd/xpbd_backend.h"

#include "xpbd_options.h"
#include "xpbd_world.h"

namespace fooball {

namespace {

/// Small-steps XPBD (see XpbdWorld) behind the Backend interface: scene order and options.
class XpbdBackend final : public Backend {
 public:
  XpbdBackend() : Backend(xpbd::xpbdOptionSpecs()) { optionsChanged(); }

  void load(const Scene& scene) override { world_.load(scene.balls, scene.box, scene.world); }

  void setWorld(const WorldSettings& world) override { world_.setWorld(world); }

  void step(double dt, std::span<const Vec2> forces) override { world_.step(dt, forces); }

  void setBall(std::size_t index, const BallDef& ball) override {
    world_.setBall(world_.particles().slotOf(index), ball);
  }

  std::size_t ballCount() const override { return world_.particles().size(); }

  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    const xpbd::Particles& particles = world_.particles();
    for (std::size_t slot = 0; slot < particles.size(); ++slot) {
      const std::uint32_t id = particles.id[slot];
      const xpbd::Particle& p = particles.particle[slot];
      positions[id] = {p.x, p.y};
      velocities[id] = {p.vx, p.vy};
    }
  }

  BackendCounters counters() const override { return world_.counters(); }

  /// "memory_bytes": every buffer the backend holds, for the benchmarks' bytes per ball.
  std::vector<Diagnostic> diagnostics() const override {
    return {{"memory_bytes", static_cast<double>(world_.memoryBytes())}};
  }

 protected:
  void optionsChanged() override {
    const xpbd::XpbdSettings settings = xpbd::readXpbdSettings(options_);
    world_.setSubsteps(settings.substeps);
    world_.setIterations(settings.iterations);
  }

 private:
  xpbd::XpbdWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeXpbdBackend() {
  return std::make_unique<XpbdBackend>();
}

}  // namespace fooball
