#include "exact/exact_backend.h"

#include "event_driven_world.h"
#include "exact_options.h"

namespace fooball {

namespace {

/// The `exact` backend: the event-driven solver behind the Backend interface.
class ExactBackend final : public Backend {
 public:
  ExactBackend() : Backend(exact::exactOptionSpecs()) { ExactBackend::optionsChanged(); }

  void load(const Scene& scene) override { world_.load(scene); }

  void setWorld(const WorldSettings& world) override { world_.setWorld(world); }

  void step(double dt, std::span<const Vec2> forces) override { world_.step(dt, forces); }

  void setBall(std::size_t index, const BallDef& ball) override { world_.setBall(index, ball); }

  std::size_t ballCount() const override { return world_.ballCount(); }

  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    for (std::size_t ball = 0; ball < world_.ballCount(); ++ball) {
      positions[ball] = world_.position(ball);
      velocities[ball] = world_.velocity(ball);
    }
  }

  BackendCounters counters() const override {
    BackendCounters counters = world_.counters();
    counters.cutShortSteps = world_.statistics().cutShortSteps;
    counters.restEnergyChange = world_.statistics().restEnergyChange;
    counters.restingBalls = world_.restingBallCount();
    return counters;
  }

  std::vector<Diagnostic> diagnostics() const override {
    const exact::EventStatistics& statistics = world_.statistics();
    return {
        {"events", static_cast<double>(statistics.events)},
        {"events_this_step", static_cast<double>(statistics.eventsThisStep)},
        {"collisions_this_step", static_cast<double>(statistics.collisionsThisStep)},
        {"rest_energy_change", statistics.restEnergyChange},
        {"rest_energy_bound", statistics.restEnergyBound},
        {"sleeps", static_cast<double>(statistics.sleeps)},
        {"wakes", static_cast<double>(statistics.wakes)},
    };
  }

 protected:
  void optionsChanged() override { world_.setLimits(exact::readEventLimits(options_)); }

 private:
  exact::EventDrivenWorld world_;
};

}  // namespace

std::unique_ptr<Backend> makeExactBackend() {
  return std::make_unique<ExactBackend>();
}

}  // namespace fooball
