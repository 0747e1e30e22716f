#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "balls.h"
#include "common/cell_lists.h"
#include "fooball/backend.h"
#include "fooball/scene.h"
#include "pair_collisions.h"
#include "worker_team.h"

namespace fooball::elastic {

/// The elastic method on one scene, without the Backend interface around it. Per substep:
/// exact free flight under gravity and drag, then every overlapping pair separated and (if
/// approaching) given the elastic impulse, then the walls. Time-stepped: collisions are found
/// after the balls overlap, so fast balls can tunnel and simultaneous contacts are resolved one
/// pair at a time.
///
/// A team of workers can share each step, and the result is bit for bit the same for any
/// number of workers: pairs are resolved in bands of grid rows (fixed by the grid, not by the
/// team), first the even bands side by side, then the odd ones. Two bands of a colour never
/// touch the same ball, and within a band the order is fixed, so who does which band does not
/// matter. The few balls too big for the grid's cells (CellLists) are met first, by one worker.
/// Sums (drag loss, wall impulse) are kept per fixed chunk of balls or per band and added in
/// that order.
class ElasticWorld {
 public:
  ElasticWorld();

  /// Replaces the balls, box and world; zeroes the counters.
  void load(std::span<const BallDef> balls, const Box& box, const WorldSettings& world);
  void setWorld(const WorldSettings& world) { world_ = world; }
  void setBall(std::size_t slot, const BallDef& ball);
  void setSubsteps(int substeps) { substeps_ = substeps; }
  /// How many workers share a step: one per `ballsPerWorker` balls, from 1 up to `maxWorkers`
  /// (the caller counts as one). `ballsPerWorker` 0 means always `maxWorkers`.
  struct WorkerPolicy {
    int maxWorkers = 1;
    std::size_t ballsPerWorker = 0;
  };
  void setWorkerPolicy(const WorkerPolicy& policy);
  /// The workers the policy gives the loaded balls.
  int workers() const { return team_->size(); }

  /// Advances by `dt` seconds; forces as in Backend::step.
  void step(double dt, std::span<const Vec2> forces);

  const Balls& balls() const { return balls_; }
  const Box& box() const { return box_; }
  const WorldSettings& world() const { return world_; }
  const BackendCounters& counters() const { return counters_; }
  std::size_t memoryBytes() const;

  /// Balls per chunk of the per-ball passes: large enough that a chunk's sums cost nothing,
  /// small enough that a team shares 10'000 balls.
  static constexpr std::size_t kBallsPerChunk = 2048;

 private:
  /// Row bands per grid, at most: enough that two workers of a colour phase stay busy, few
  /// enough that each band is many rows tall and the rows two bands share are few.
  static constexpr int kMaxBands = 64;

  /// At most one ball in this many is left out of the grid as oversized: a few big balls are
  /// cheap to meet one by one, many are not.
  static constexpr std::size_t kBallsPerOversized = 64;

  /// Balls are re-sorted by cell every this many substeps: often enough that neighbours stay
  /// close in memory, rarely enough that the move costs little next to the collision pass.
  static constexpr int kSubstepsPerReorder = 16;

  class StepJob;

  /// One worker's scratch and sums, on cache lines of its own: two workers writing to one line
  /// would pass it back and forth on every write.
  struct alignas(64) WorkerState {
    NeighbourSlots neighbours;
    std::uint64_t impulses = 0;  ///< ball–ball impulses in this step
  };

  /// What the walls and drag did to one chunk of balls (or one band of grid rows) in a step;
  /// summed in a fixed order afterwards.
  struct ChunkTally {
    double dragLoss = 0.0;  ///< J
    std::uint64_t wallBounces = 0;
    double wallImpulse = 0.0;  ///< N·s
  };

  /// Sizes the grid, bands and tallies for the loaded balls, and the team by the policy.
  void layout();
  void applyKicks(double dt, std::span<const Vec2> forces);

  Box box_;
  WorldSettings world_;
  Balls balls_;
  common::CellLists cells_;
  BackendCounters counters_;
  int substeps_ = 1;
  WorkerPolicy workerPolicy_;
  int substepsSinceReorder_ = 0;
  int rowsPerBand_ = 1;
  std::vector<ChunkTally> chunkTallies_;
  std::vector<ChunkTally> bandTallies_;
  ChunkTally oversizedTally_;
  std::vector<SweepEntry> oversizedSweep_;  ///< one per oversized ball
  std::vector<WorkerState> workers_;
  std::atomic<int> nextEvenBand_{0};
  std::atomic<int> nextOddBand_{0};
  std::unique_ptr<WorkerTeam> team_;
};

}  // namespace fooball::elastic
