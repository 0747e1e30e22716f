#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fooball/simulation.h"

namespace fooball {

/// The moments a run group can rewind to (RunGroup::rewindTo), within a bound on the bytes kept.
///
/// The guarantee (README, "Rewind"): rewinding to a moment and stepping forward gives the same
/// positions, velocities, counters, clock and energy budget, bit for bit, as the run had there,
/// on every backend. A saved state does not give that: a backend's future depends on more than
/// its balls (Box2D's warm-start cache, xpbd's contact memory, the exact solver's event queue,
/// even elastic's storage order, which it re-sorts every 16 substeps and which orders its sums:
/// measured, a dense heap loaded from its state drifts off in the last bits), and copying those
/// internals out of five methods, two of them third-party engines, is neither cheap nor safe.
/// So the history keeps anchors: each simulation's whole state at a moment where every backend
/// had just been loaded from that state (RunGroup::restartHistory, and RunGroup reloads them
/// when anchorDue()), and the forces the tools applied in each step since; a moment is a step
/// count, reached by loading the latest anchor at or before it and re-stepping — deterministic,
/// by the backend contract — or, forward of where the runs are, by stepping on. A new anchor
/// is due every stepsPerAnchor() steps, so a rewind re-steps a bounded number of ball-steps
/// however long the history; the price is a reload of every backend there, which is to the
/// run what a setting change is (Box2D forgets its warm-start cache). Edits are not logged:
/// they start a new history.
///
/// A moment is marked every kStepsPerMoment steps. Continuing from a rewound moment drops the
/// moments, anchors and forces after it: that future no longer exists. When the kept bytes pass
/// the bound the oldest anchor goes with the moments before the next; with only one left the
/// history starts afresh from now, which the run group does.
class RunHistory {
 public:
  /// Bytes the history may hold by default: 256 MB.
  static constexpr std::size_t kDefaultBound = std::size_t{256} << 20;
  /// Steps between moments: 10 per second at 60 steps per second.
  static constexpr std::uint64_t kStepsPerMoment = 6;
  /// Ball-steps (steps × balls of every simulation) between anchors: what one rewind re-steps
  /// at the most. At 10'000 balls and the app's defaults that is 0.18 s on elastic and 4.6 s
  /// on Box2D, about what those steps took when they ran (benchmarks/rewind_benchmark.cpp);
  /// fewer, and the reloads would come oftener. A 38-ball scene is reloaded every ~15 min.
  static constexpr std::uint64_t kDefaultBallStepsPerAnchor = 2'000'000;
  /// Steps between anchors at the least (1 s at 60 steps per second): a huge scene is not
  /// reloaded every step, and its rewind re-steps at most this many steps.
  static constexpr std::uint64_t kMinStepsPerAnchor = 60;

  /// Forgets every moment and keeps `simulations` now as the first anchor, each backendFresh().
  void start(std::span<Simulation* const> simulations);
  /// After each lockstep step: drops the future of a rewound moment, logs the tools' forces,
  /// marks a moment when one is due, and drops the oldest anchors while over the bound. False
  /// when the history has outgrown its bound with one anchor left (the caller starts it afresh).
  bool record(std::span<Simulation* const> simulations);
  /// After record(): whether the moment just marked should become an anchor. The caller then
  /// reloads every backend from its simulation's state and calls anchor().
  bool anchorDue(std::span<Simulation* const> simulations) const;
  /// Keeps `simulations` now, each backendFresh(), as an anchor at the newest moment.
  void anchor(std::span<Simulation* const> simulations);
  /// Before a rewind from now: marks a moment now unless the last is now, so the user can come
  /// back to it.
  void keepNow(std::span<Simulation* const> simulations);
  /// Puts every simulation at moment `index` (< size()): forward of where they are by stepping
  /// on, else from the latest anchor at or before it.
  void restore(std::size_t index, std::span<Simulation* const> simulations);

  std::size_t size() const { return moments_.size(); }
  /// s, the time of moment `index`.
  double time(std::size_t index) const { return moments_.at(index).time; }
  /// The moment the simulations are at or last passed (the last one unless rewound).
  std::size_t position() const { return position_; }
  /// Bytes held, vectors by capacity.
  std::size_t bytes() const { return bytes_; }
  std::size_t bound() const { return bound_; }
  void setBound(std::size_t bytes) { bound_ = bytes; }
  std::size_t anchorCount() const { return anchors_.size(); }
  /// Steps between anchors for `balls` balls in all the simulations.
  std::uint64_t stepsPerAnchor(std::size_t balls) const;
  void setBallStepsPerAnchor(std::uint64_t ballSteps) { ballStepsPerAnchor_ = ballSteps; }

 private:
  struct Moment {
    std::uint64_t steps = 0;  ///< the simulations' step count
    double time = 0.0;        ///< s
  };
  /// A moment every simulation can be re-stepped from.
  struct Anchor {
    std::uint64_t steps = 0;
    std::vector<Simulation::State> states;  ///< one per simulation, each taken backendFresh()
  };
  /// The tools' forces in one step of one simulation.
  struct ForcedStep {
    std::uint64_t step = 0;  ///< the simulation's step count before it
    std::vector<Vec2> forces;
  };

  void mark(const Simulation& simulation);
  void keepAnchor(std::span<Simulation* const> simulations);
  /// Drops the oldest anchor and the moments and forces before the next one.
  void dropOldestAnchor();
  void keepWithinBound();
  /// The latest anchor at or before `steps`.
  const Anchor& anchorAt(std::uint64_t steps) const;
  /// Steps `simulation` (simulation `k` in stepping order) on from where it is to `steps`.
  void stepOn(std::size_t k, Simulation& simulation, std::uint64_t steps) const;
  void recount();

  std::vector<Moment> moments_;
  std::vector<Anchor> anchors_;                       ///< oldest first, the first at moment 0
  std::vector<std::vector<ForcedStep>> forcedSteps_;  ///< one log per simulation
  std::size_t position_ = 0;
  std::size_t bytes_ = 0;
  std::size_t bound_ = kDefaultBound;
  std::uint64_t ballStepsPerAnchor_ = kDefaultBallStepsPerAnchor;
};

}  // namespace fooball
