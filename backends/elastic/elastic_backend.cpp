#include "elastic/elastic_backend.h"

#include <algorithm>

#include "ball_arrays.h"
#include "fooball/cell_grid.h"
#include "free_flight.h"
#include "pair_collisions.h"
#include "wall_bounce.h"

namespace fooball {

namespace {

/// Balls are re-sorted by cell every this many substeps: often enough that neighbours stay
/// close in memory, rarely enough that the copy costs little next to the collision pass.
constexpr int kSubstepsPerReorder = 16;

/// The seed's method done right: per substep, exact free flight under gravity and drag, then
/// every overlapping pair separated and (if approaching) given the elastic impulse, then the
/// walls. Time-stepped: collisions are found after the balls overlap, so fast balls can tunnel
/// and simultaneous contacts are resolved one pair at a time.
class ElasticBackend final : public Backend {
 public:
  ElasticBackend()
      : Backend({{"substeps", "solver substeps per step (more: less overlap, less tunnelling)", 4,
                  1, 1000, true}}) {
    optionsChanged();
  }

  void load(const Scene& scene) override {
    name_ = scene.name;
    box_ = scene.box;
    world_ = scene.world;
    colors_.resize(scene.balls.size());
    for (std::size_t i = 0; i < scene.balls.size(); ++i)
      colors_[i] = scene.balls[i].color;
    balls_.assign(scene.balls);
    counters_ = {};
    substepsSinceReorder_ = kSubstepsPerReorder;
    updateLargestRadius();
  }

  Scene save() const override {
    Scene scene{name_, box_, world_, std::vector<BallDef>(balls_.size())};
    for (std::size_t slot = 0; slot < balls_.size(); ++slot) {
      const std::uint32_t id = balls_.id[slot];
      scene.balls[id] = {{balls_.x[slot], balls_.y[slot]},
                         {balls_.vx[slot], balls_.vy[slot]},
                         balls_.radius[slot],
                         balls_.mass[slot],
                         colors_[id]};
    }
    return scene;
  }

  void setWorld(const WorldSettings& world) override { world_ = world; }

  void step(double dt, std::span<const Vec2> forces) override {
    if (!forces.empty()) applyKicks(dt, forces);
    const double h = dt / substeps_;
    for (int substep = 0; substep < substeps_; ++substep) {
      counters_.dragLoss += elastic::flyFreely(balls_, h, world_.gravity, world_.airResistance);
      if (world_.ballCollisions) {
        sortIntoCells();
        elastic::collidePairs(balls_, grid_, counters_);
      }
      elastic::bounceOffWalls(balls_, box_, world_.walls, world_.gravity, counters_);
    }
  }

  void setBall(std::size_t index, const BallDef& ball) override {
    const std::size_t slot = balls_.slotOf(index);
    balls_.x[slot] = ball.position.x;
    balls_.y[slot] = ball.position.y;
    balls_.vx[slot] = ball.velocity.x;
    balls_.vy[slot] = ball.velocity.y;
    balls_.radius[slot] = ball.radius;
    balls_.mass[slot] = ball.mass;
    colors_[index] = ball.color;
    updateLargestRadius();
  }

  std::size_t ballCount() const override { return balls_.size(); }

  void readState(std::span<Vec2> positions, std::span<Vec2> velocities) const override {
    for (std::size_t slot = 0; slot < balls_.size(); ++slot) {
      const std::uint32_t id = balls_.id[slot];
      positions[id] = {balls_.x[slot], balls_.y[slot]};
      velocities[id] = {balls_.vx[slot], balls_.vy[slot]};
    }
  }

  BackendCounters counters() const override { return counters_; }

 protected:
  void optionsChanged() override { substeps_ = static_cast<int>(options_.value("substeps")); }

 private:
  void applyKicks(double dt, std::span<const Vec2> forces) {
    for (std::size_t slot = 0; slot < balls_.size(); ++slot) {
      const Vec2 force = forces[balls_.id[slot]];
      balls_.vx[slot] += force.x * dt / balls_.mass[slot];
      balls_.vy[slot] += force.y * dt / balls_.mass[slot];
    }
  }

  void sortIntoCells() {
    const double cellSize = 2.0 * largestRadius_;
    grid_.build(balls_.x, balls_.y, box_.width, box_.height, cellSize);
    if (++substepsSinceReorder_ < kSubstepsPerReorder) return;
    // Move balls into cell order, then rebuild: the rebuilt grid's order is the identity, so the
    // pair pass walks memory sequentially.
    balls_.permute(grid_.order(), reorderScratch_, idScratch_);
    grid_.build(balls_.x, balls_.y, box_.width, box_.height, cellSize);
    substepsSinceReorder_ = 0;
  }

  void updateLargestRadius() {
    largestRadius_ =
        balls_.radius.empty() ? 1.0 : *std::max_element(balls_.radius.begin(), balls_.radius.end());
  }

  std::string name_;
  Box box_;
  WorldSettings world_;
  elastic::BallArrays balls_;
  std::vector<std::uint32_t> colors_;  ///< by scene index; drawing only, kept out of the hot loop
  BackendCounters counters_;
  CellGrid grid_;
  std::vector<double> reorderScratch_;
  std::vector<std::uint32_t> idScratch_;
  double largestRadius_ = 1.0;  ///< m
  int substeps_ = 4;
  int substepsSinceReorder_ = 0;
};

}  // namespace

std::unique_ptr<Backend> makeElasticBackend() {
  return std::make_unique<ElasticBackend>();
}

}  // namespace fooball
