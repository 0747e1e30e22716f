#include "elastic_world.h"

#include <algorithm>
#include <numeric>

#include "common/exact_size.h"

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
  balls_.touches[slot] = 0;  // an edited ball begins its contacts anew
  layout();
}

void ElasticWorld::setWorkerPolicy(const WorkerPolicy& policy) {
  workerPolicy_ = policy;
  layout();
}

namespace {

std::size_t chunkCount(std::size_t balls) {
  return (balls + ElasticWorld::kBallsPerChunk - 1) / ElasticWorld::kBallsPerChunk;
}

}  // namespace

void ElasticWorld::layout() {
  const int most = std::max(1, workerPolicy_.maxWorkers);
  const std::size_t perWorker = workerPolicy_.ballsPerWorker;
  const int workers = perWorker == 0
                          ? most
                          : static_cast<int>(std::clamp<std::size_t>(
                                balls_.size() / perWorker, 1, static_cast<std::size_t>(most)));
  if (workers != team_->size()) {
    team_.reset();  // the old workers stop before the new ones start
    team_ = std::make_unique<WorkerTeam>(workers);
    workers_.resize(static_cast<std::size_t>(workers));
  }
  cells_.layout(balls_.size(), box_.width, box_.height,
                2.0 * common::gridRadius<Ball>(balls_.ball, kBallsPerOversized), team_->size());
  const auto oversized =
      std::count_if(balls_.ball.begin(), balls_.ball.end(),
                    [&](const Ball& ball) { return ball.radius > cells_.oversizedRadius(); });
  common::resizeExactly(oversizedSweep_, static_cast<std::size_t>(oversized));
  rowsPerBand_ = std::max(1, (cells_.rows() + kMaxBands - 1) / kMaxBands);
  bandTallies_.resize(static_cast<std::size_t>((cells_.rows() + rowsPerBand_ - 1) / rowsPerBand_));
  common::resizeExactly(chunkTallies_, chunkCount(balls_.size()));
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
         oversizedSweep_.capacity() * sizeof(SweepEntry) +
         std::accumulate(workers_.begin(), workers_.end(), std::size_t{0},
                         [](std::size_t sum, const WorkerState& worker) {
                           return sum + worker.neighbours.memoryBytes();
                         });
}

}  // namespace fooball::elastic
