#include "fooball/run_history.h"

#include <algorithm>

namespace fooball {

void RunHistory::recount() {
  bytes_ = moments_.capacity() * sizeof(Moment) +
           forcedSteps_.capacity() * sizeof(std::vector<ForcedStep>) +
           first_.capacity() * sizeof(Simulation::State);
  for (const Simulation::State& state : first_)
    bytes_ += state.bytes() - sizeof(Simulation::State);
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

void RunHistory::start(std::span<Simulation* const> simulations) {
  moments_.clear();
  first_.clear();
  for (const Simulation* simulation : simulations)
    first_.push_back(simulation->state());
  forcedSteps_.assign(simulations.size(), {});
  mark(*simulations.front());
  recount();
}

bool RunHistory::record(std::span<Simulation* const> simulations) {
  if (moments_.empty() || simulations.size() != first_.size()) {
    start(simulations);
    return true;
  }
  const std::uint64_t steps = simulations.front()->steps();
  if (position_ + 1 < moments_.size()) {  // continued from a rewind: the future goes
    moments_.resize(position_ + 1);
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
  return bytes_ <= bound_;
}

void RunHistory::keepNow(std::span<Simulation* const> simulations) {
  if (moments_.empty() || position_ + 1 < moments_.size()) return;
  if (simulations.front()->steps() > moments_.back().steps) {
    mark(*simulations.front());
    recount();
  }
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
  for (std::size_t k = 0; k < simulations.size(); ++k) {
    Simulation& simulation = *simulations[k];
    if (simulation.steps() > target.steps) simulation.restore(first_[k]);
    stepOn(k, simulation, target.steps);
  }
  position_ = index;
}

}  // namespace fooball
