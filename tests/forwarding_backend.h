#pragma once

#include <memory>
#include <span>
#include <utility>

#include "fooball/backend.h"

namespace fooball::testing {

/// A backend that passes every call on to a real one: a test derives from it and overrides what
/// it makes go wrong (a step that throws, a runaway step count).
class ForwardingBackend : public Backend {
 public:
  explicit ForwardingBackend(std::unique_ptr<Backend> inner)
      : Backend({}), inner_(std::move(inner)) {}
  void load(const Scene& scene) override { inner_->load(scene); }
  void setWorld(const WorldSettings& world) override { inner_->setWorld(world); }
  void step(double dt, std::span<const Vec2> forces) override { inner_->step(dt, forces); }
  void setBall(std::size_t index, const BallDef& ball) override { inner_->setBall(index, ball); }
  std::size_t ballCount() const override { return inner_->ballCount(); }
  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    inner_->readState(positions, velocities);
  }
  BackendCounters counters() const override { return inner_->counters(); }

 private:
  std::unique_ptr<Backend> inner_;
};

}  // namespace fooball::testing
