#include "fooball/run_history.h"

#include <algorithm>

namespace fooball {

void RunHistory::recount() {
  bytes_ = moments_.capacity() * sizeof(Moment) + anchors_.capacity() * sizeof(Anchor) +
           forcedSteps_.capacity() * sizeof(std::vector<ForcedStep>);
  for (const Anchor& anchor : anchors_) {
    bytes_ += anchor.states.capacity() * sizeof(Simulation::State);
    for (const Simulation::State& state : anchor.states)
      bytes_ += state.bytes() - sizeof(Simulation::State);
  }
  for (const auto& log : forcedSteps_) {
    bytes_ += log.capacity() * sizeof(ForcedStep);
    for (const ForcedStep& step : log)
      bytes_ += step.forces.capacity() * sizeof(Vec2);
  }
}

void RunHistory::mark(const Simulation& simulation) {
  moments_.push_back({simulation.steps(), simulation.time()});
  position_ = moments_.size() - 1;
}

void RunHistory::keepAnchor(std::span<Simulation* const> simulations) {
  Anchor& anchor = anchors_.emplace_back();
  anchor.steps = simulations.front()->steps();
  for (const Simulation* simulation : simulations)
    anchor.states.push_back(simulation->state());
}

void RunHistory::start(std::span<Simulation* const> simulations) {
  moments_.clear();
  anchors_.clear();
  keepAnchor(simulations);
  forcedSteps_.assign(simulations.size(), {});
  mark(*simulations.front());
  recount();
}

std::uint64_t RunHistory::stepsPerAnchor(std::size_t balls) const {
  const std::uint64_t perBall = std::max<std::uint64_t>(balls, 1);
  return std::max(kMinStepsPerAnchor, (ballStepsPerAnchor_ + perBall - 1) / perBall);
}

void RunHistory::dropOldestAnchor() {
  anchors_.erase(anchors_.begin());
  const std::uint64_t first = anchors_.front().steps;
  const auto kept = std::find_if(moments_.begin(), moments_.end(),
                                 [first](const Moment& moment) { return moment.steps >= first; });
  position_ -= static_cast<std::size_t>(kept - moments_.begin());
  moments_.erase(moments_.begin(), kept);
  for (auto& log : forcedSteps_)
    std::erase_if(log, [first](const ForcedStep& forced) { return forced.step < first; });
  recount();
}

void RunHistory::keepWithinBound() {
  while (bytes_ > bound_ && anchors_.size() > 1)
    dropOldestAnchor();
}

bool RunHistory::record(std::span<Simulation* const> simulations) {
  if (moments_.empty() || simulations.size() != anchors_.front().states.size()) {
    start(simulations);
    return true;
  }
  const std::uint64_t steps = simulations.front()->steps();
  if (position_ + 1 < moments_.size()) {  // continued from a rewind: the future goes
    const std::uint64_t rewound = moments_[position_].steps;
    moments_.resize(position_ + 1);
    std::erase_if(anchors_, [rewound](const Anchor& anchor) { return anchor.steps > rewound; });
    for (auto& log : forcedSteps_)
      std::erase_if(log, [steps](const ForcedStep& forced) { return forced.step >= steps - 1; });
  }
  bool grew = false;
  for (std::size_t k = 0; k < simulations.size(); ++k) {
    const std::span<const Vec2> forces = simulations[k]->lastForces();
    if (!forces.empty()) {
      forcedSteps_[k].push_back({steps - 1, {forces.begin(), forces.end()}});
      grew = true;
    }
  }
  if (steps >= moments_.back().steps + kStepsPerMoment) {
    mark(*simulations.front());
    grew = true;
  }
  position_ = moments_.size() - 1;
  if (grew) recount();
  keepWithinBound();
  return bytes_ <= bound_;
}

bool RunHistory::anchorDue(std::span<Simulation* const> simulations) const {
  const std::uint64_t steps = simulations.front()->steps();
  if (moments_.empty() || moments_.back().steps != steps) return false;
  std::size_t balls = 0;
  for (const Simulation* simulation : simulations)
    balls += simulation->ballCount();
  return steps >= anchors_.back().steps + stepsPerAnchor(balls);
}

void RunHistory::anchor(std::span<Simulation* const> simulations) {
  keepAnchor(simulations);
  recount();
  keepWithinBound();
}

void RunHistory::keepNow(std::span<Simulation* const> simulations) {
  if (moments_.empty() || position_ + 1 < moments_.size()) return;
  if (simulations.front()->steps() > moments_.back().steps) {
    mark(*simulations.front());
    recount();
  }
}

const RunHistory::Anchor& RunHistory::anchorAt(std::uint64_t steps) const {
  const auto after = std::upper_bound(
      anchors_.begin(), anchors_.end(), steps,
      [](std::uint64_t wanted, const Anchor& anchor) { return wanted < anchor.steps; });
  return *std::prev(after);  // the first anchor is at the first moment: never before it
}

void RunHistory::stepOn(std::size_t k, Simulation& simulation, std::uint64_t steps) const {
  const std::vector<ForcedStep>& log = forcedSteps_[k];
  auto forced = std::lower_bound(
      log.begin(), log.end(), simulation.steps(),
      [](const ForcedStep& logged, std::uint64_t step) { return logged.step < step; });
  while (simulation.steps() < steps) {
    if (forced != log.end() && forced->step == simulation.steps()) {
      simulation.replayStep(forced->forces);
      ++forced;
    } else {
      simulation.replayStep({});
    }
  }
}

void RunHistory::restore(std::size_t index, std::span<Simulation* const> simulations) {
  const Moment& target = moments_.at(index);
  const Anchor& anchor = anchorAt(target.steps);
  for (std::size_t k = 0; k < simulations.size(); ++k) {
    Simulation& simulation = *simulations[k];
    // Stepping on is exact only from the anchor's side: a run behind it never had the reload.
    if (simulation.steps() > target.steps || simulation.steps() < anchor.steps)
      simulation.restore(anchor.states[k]);
    stepOn(k, simulation, target.steps);
  }
  position_ = index;
}

}  // namespace fooball
