// One step of ElasticWorld: the phases every worker runs, and where they meet.

#include <algorithm>
#include <type_traits>

#include "common/work_share.h"
#include "elastic_world.h"
#include "free_flight.h"
#include "pair_collisions.h"
#include "wall_bounce.h"

namespace fooball::elastic {

namespace {

/// The per-ball work between two pair searches, in this order.
struct BallWorkParts {
  bool walls;  ///< the walls of the substep that ends
  bool fly;    ///< the free flight of the substep that starts
  bool cells;  ///< the cell of the ball's new centre, for the next pair search
  common::CellOrder nextOrder =
      common::CellOrder::FromLowerLeft;  ///< how the next pair search numbers cells
};

}  // namespace

/// One step as every worker runs it; workers meet at team.sync() between phases.
///
/// With collisions on, the per-ball work of the walls and of the next substep's flight is done
/// row by row inside the pair search, as soon as no pair is left to touch a row's balls: they
/// are still in cache, and the step makes one pass over memory per substep instead of two.
/// A ball in row r is final once rows r−1 and r have been searched (a cell meets its right
/// neighbour and the three cells above). So a band finishes its rows after the first as it
/// goes, and its first row once the band below is done: right away for an odd band, and for an
/// even band at the end of the odd band below it.
class ElasticWorld::StepJob {
 public:
  StepJob(ElasticWorld& world, double h) : w_(world), h_(h) {}

  void operator()(int worker) {
    if (!w_.world_.ballCollisions) {
      for (int substep = 0; substep < w_.substeps_; ++substep)
        passOverChunks(worker, {substep > 0, true, false});
      passOverChunks(worker, {true, false, false});
      return;
    }
    passOverChunks(worker, {false, true, true, cellOrder(0)});
    for (int substep = 0; substep < w_.substeps_; ++substep) {
      const bool last = substep + 1 == w_.substeps_;
      collide(worker, substep, {true, !last, !last, cellOrder(substep + 1)});
    }
  }

 private:
  /// How the pair search of this step's `substep` numbers the cells: from the lower left and
  /// the upper right by turns, counted across steps (kSubstepsPerReorder is even), and from the
  /// lower left on the substeps that reorder the balls, so memory keeps that order.
  common::CellOrder cellOrder(int substep) const {
    return (w_.substepsSinceReorder_ + substep) % 2 == 1 ? common::CellOrder::FromLowerLeft
                                                         : common::CellOrder::FromUpperRight;
  }

  /// Calls f(std::true_type) or f(std::false_type): turns a flag into a template argument, so
  /// the per-ball loop carries no tests of it.
  template <class F>
  static void withFlag(bool flag, F&& f) {
    if (flag) {
      f(std::true_type{});
    } else {
      f(std::false_type{});
    }
  }

  /// Calls loop(work), where work(ball, slot) does `parts` to one ball; what the walls and drag
  /// did is added to `tally`.
  template <class Loop>
  void withBallWork(BallWorkParts parts, ChunkTally& tally, Loop&& loop) {
    const WorldSettings& world = w_.world_;
    const WallBounce wallBounce(w_.box_, world.walls, world.gravity);
    common::CellLists& cells = w_.cells_;
    const auto run = [&](auto walls, auto fly, auto findCells, const auto& flight) {
      WallTally wallTally;
      double dragLoss = 0.0;
      loop([&](Ball& ball, std::size_t slot) {
        if constexpr (walls) wallBounce.bounce(ball, w_.balls_.touches[slot], wallTally);
        if constexpr (fly) dragLoss += flight.fly(ball);
        if constexpr (findCells)
          cells.setCell(slot, cells.cellOf(ball.x, ball.y, ball.radius, parts.nextOrder));
      });
      tally.dragLoss += dragLoss;
      tally.wallBounces += wallTally.bounces;
      tally.wallImpulse += wallTally.impulse;
    };
    withFlag(parts.walls, [&](auto walls) {
      withFlag(parts.fly, [&](auto fly) {
        withFlag(parts.cells, [&](auto findCells) {
          if (world.airResistance == 0.0) {
            run(walls, fly, findCells, FlightWithoutDrag(h_, world.gravity));
          } else {
            run(walls, fly, findCells, FlightWithDrag(h_, world.gravity, world.airResistance));
          }
        });
      });
    });
  }

  /// `parts` for the balls of this worker's chunks.
  void passOverChunks(int worker, BallWorkParts parts) {
    std::vector<Ball>& balls = w_.balls_.ball;
    const common::Share chunks = common::shareOf(w_.chunkTallies_.size(), worker, w_.team_->size());
    for (std::size_t chunk = chunks.begin; chunk < chunks.end; ++chunk) {
      const std::size_t end = std::min(balls.size(), (chunk + 1) * kBallsPerChunk);
      withBallWork(parts, w_.chunkTallies_[chunk], [&](auto&& work) {
        for (std::size_t slot = chunk * kBallsPerChunk; slot < end; ++slot)
          work(balls[slot], slot);
      });
    }
  }

  /// `parts` for the balls of grid row `row`.
  void finishRow(int row, BallWorkParts parts, ChunkTally& tally) {
    std::vector<Ball>& balls = w_.balls_.ball;
    const int columns = w_.cells_.columns();
    const auto slots = w_.cells_.slotsIn(row * columns, (row + 1) * columns);
    withBallWork(parts, tally, [&](auto&& work) {
      for (const std::uint32_t slot : slots)
        work(balls[slot], slot);
    });
  }

  /// The oversized balls' pairs (the cells numbered in `order`), then `parts` for the oversized
  /// balls: no pair of the bands touches them.
  void collideOversized(common::CellOrder order, BallWorkParts parts) {
    w_.workers_[0].impulses +=
        elastic::collideOversized(w_.balls_.ball, w_.cells_, order, w_.oversizedSweep_);
    std::vector<Ball>& balls = w_.balls_.ball;
    withBallWork(parts, w_.oversizedTally_, [&](auto&& work) {
      for (const std::uint32_t slot : w_.cells_.oversizedSlots())
        work(balls[slot], slot);
    });
  }

  /// The pair search of one substep, finishing every ball with `parts` on the way.
  void collide(int worker, int substep, BallWorkParts parts) {
    WorkerTeam& team = *w_.team_;
    if (worker == 0) {
      w_.nextEvenBand_ = 0;
      w_.nextOddBand_ = 0;
    }
    team.sync();
    w_.cells_.countShare(worker);
    team.sync();
    w_.cells_.sortShare(worker, cellOrder(substep));
    team.sync();
    const bool reorder = (w_.substepsSinceReorder_ + substep + 1) % kSubstepsPerReorder == 0;
    const bool oversized = !w_.oversizedSweep_.empty();
    if (reorder || oversized) {
      if (worker == 0) {
        // Move the balls into cell order: the sorted slots become the identity, so the pair
        // pass walks memory sequentially.
        if (reorder) w_.balls_.permute(w_.cells_.sortedSlots(), w_.cells_.cellsBySlot());
        if (oversized) collideOversized(cellOrder(substep), parts);
      }
      team.sync();
    }
    collideBands(worker, 0, w_.nextEvenBand_, parts);
    team.sync();
    collideBands(worker, 1, w_.nextOddBand_, parts);
    team.sync();
  }

  /// Takes bands of one colour (0 even, 1 odd) until none is left.
  void collideBands(int worker, int colour, std::atomic<int>& nextBand, BallWorkParts parts) {
    const int rows = w_.cells_.rows();
    const int rowsPerBand = w_.rowsPerBand_;
    std::uint64_t impulses = 0;
    for (;;) {
      const int band = 2 * nextBand.fetch_add(1, std::memory_order_relaxed) + colour;
      const int firstRow = band * rowsPerBand;
      if (firstRow >= rows) break;
      const int endRow = std::min(rows, firstRow + rowsPerBand);
      ChunkTally& tally = w_.bandTallies_[band];
      for (int row = firstRow; row < endRow; ++row) {
        impulses +=
            collideRows(w_.balls_.ball, w_.cells_, row, row + 1, w_.workers_[worker].neighbours);
        if (row > firstRow || colour == 1 || band == 0) finishRow(row, parts, tally);
      }
      if (colour == 1 && endRow < rows) finishRow(endRow, parts, tally);
    }
    w_.workers_[worker].impulses += impulses;
  }

  ElasticWorld& w_;
  double h_;  ///< s, one substep
};

void ElasticWorld::step(double dt, std::span<const Vec2> forces) {
  if (!forces.empty()) applyKicks(dt, forces);
  StepJob job(*this, dt / substeps_);
  team_->run(job);
  substepsSinceReorder_ = (substepsSinceReorder_ + substeps_) % kSubstepsPerReorder;
  const auto addTally = [&](ChunkTally& tally) {
    counters_.dragLoss += tally.dragLoss;
    counters_.wallCollisions += tally.wallBounces;
    counters_.wallImpulse += tally.wallImpulse;
    tally = {};
  };
  for (auto* tallies : {&chunkTallies_, &bandTallies_})
    std::for_each(tallies->begin(), tallies->end(), addTally);
  addTally(oversizedTally_);
  for (WorkerState& worker : workers_) {
    counters_.ballCollisions += worker.impulses;
    worker.impulses = 0;
  }
}

}  // namespace fooball::elastic
