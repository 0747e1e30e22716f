#include "elastic_world.h"

#include <algorithm>
#include <numeric>

namespace fooball::elastic {

ElasticWorld::ElasticWorld() : team_(std::make_unique<WorkerTeam>(1)) {
  workers_.resize(1);
}

void ElasticWorld::load(std::span<const BallDef> balls, const Box& box,
                        const WorldSettings& world) {
  box_ = box;
  world_ = world;
  balls_.assign(balls);
  counters_ = {};
  // Scene order is usually random in space: sort by cell in the first substep.
  substepsSinceReorder_ = kSubstepsPerReorder - 1;
  layout();
}

void ElasticWorld::setBall(std::size_t slot, const BallDef& ball) {
  balls_.ball[slot] = {ball.position.x, ball.position.y, ball.velocity.x,
                       ball.velocity.y, ball.radius,     ball.mass};
  layout();
}

void ElasticWorld::setThreads(int threads) {
  if (threads == team_->size()) return;
  team_.reset();  // the old workers stop before the new ones start
  team_ = std::make_unique<WorkerTeam>(threads);
  workers_.resize(static_cast<std::size_t>(threads));
  layout();
}

namespace {

std::size_t chunkCount(std::size_t balls) {
  return (balls + ElasticWorld::kBallsPerChunk - 1) / ElasticWorld::kBallsPerChunk;
}

}  // namespace

void ElasticWorld::layout() {
  double largestRadius = balls_.size() == 0 ? 1.0 : 0.0;  // m
  for (const Ball& ball : balls_.ball)
    largestRadius = std::max(largestRadius, ball.radius);
  cells_.layout(balls_.size(), box_.width, box_.height, 2.0 * largestRadius, team_->size());
  rowsPerBand_ = std::max(1, (cells_.rows() + kMaxBands - 1) / kMaxBands);
  bandTallies_.resize(static_cast<std::size_t>((cells_.rows() + rowsPerBand_ - 1) / rowsPerBand_));
  chunkTallies_.resize(chunkCount(balls_.size()));
  chunkTallies_.shrink_to_fit();
}

void ElasticWorld::applyKicks(double dt, std::span<const Vec2> forces) {
  for (std::size_t slot = 0; slot < balls_.size(); ++slot) {
    const Vec2 force = forces[balls_.id[slot]];
    Ball& ball = balls_.ball[slot];
    ball.vx += force.x * dt / ball.mass;
    ball.vy += force.y * dt / ball.mass;
  }
}

std::size_t ElasticWorld::memoryBytes() const {
  return balls_.memoryBytes() + cells_.memoryBytes() +
         (chunkTallies_.capacity() + bandTallies_.capacity()) * sizeof(ChunkTally) +
         std::accumulate(workers_.begin(), workers_.end(), std::size_t{0},
                         [](std::size_t sum, const WorkerState& worker) {
                           return sum + worker.neighbours.memoryBytes();
                         });
}

}  // namespace fooball::elastic
