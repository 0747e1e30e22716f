#include "xpbd/xpbd_backend.h"

#include "xpbd_world.h"

namespace fooball {

namespace {

/// Small-steps XPBD (see XpbdWorld) behind the Backend interface: scene order and options.
class XpbdBackend final : public Backend {
 public:
  XpbdBackend()
      : Backend({{"substeps", "solver substeps per step (more: less tunnelling and overlap)",
                  kDefaultSubsteps, 1, 1000, true, OptionRole::Substeps},
                 {"iterations",
                  "Gauss–Seidel sweeps per substep of the contact projection and of the velocity "
                  "pass (more: less energy error where contacts share a ball)",
                  kDefaultIterations, 1, 100, true, OptionRole::Iterations}}) {
    optionsChanged();
  }

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
    world_.setSubsteps(static_cast<int>(options_.value("substeps")));
    world_.setIterations(static_cast<int>(options_.value("iterations")));
  }

 private:
  /// Substeps per step, measured on the gas preset (docs/performance.md, "Speed against
  /// accuracy"): 8 leave no overlap at the end of a step (2e-14 r, against 0.009 r at 4), halve
  /// the trajectory error of 4 and put the gas's tunnelling speed at 96 m/s, twenty times its
  /// fastest ball; 16 would halve the energy loss again at twice the cost.
  static constexpr double kDefaultSubsteps = 8;
  /// Sweeps per substep: one (Müller's single velocity pass) loses a tenth of the gas's energy in
  /// 20 s at any substep count, four lose 0.17% (the passes then meet the restitution targets of
  /// contacts that share a ball), for 20–40% more cost per step.
  static constexpr double kDefaultIterations = 4;

  xpbd::XpbdWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeXpbdBackend() {
  return std::make_unique<XpbdBackend>();
}

}  // namespace fooball
