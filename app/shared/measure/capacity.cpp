#include "capacity.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "fooball/standard_scenes.h"
#include "step_timing.h"

namespace fooball::measure {

namespace {

std::string_view optionName(std::string_view assignment) {
  return assignment.substr(0, assignment.find('='));
}

/// Applies the options of `assignments` that `backend` has; returns those it took.
std::vector<std::string> applyOptions(Backend& backend, std::span<const std::string> assignments) {
  std::vector<std::string> taken;
  for (const std::string& assignment : assignments) {
    if (!backend.options().has(optionName(assignment))) continue;
    backend.setOptionFromText(assignment);
    taken.push_back(assignment);
  }
  return taken;
}

}  // namespace

void checkCapacitySettings(std::span<const BackendInfo> backends,
                           const CapacitySettings& settings) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (!positive(settings.budgetMs)) throw std::invalid_argument("budget: must be a number > 0");
  if (!positive(settings.dt)) throw std::invalid_argument("dt: must be a number > 0");
  if (!(settings.packingFraction > 0.0 && settings.packingFraction < 0.9)) {
    throw std::invalid_argument("packing fraction: must be in (0, 0.9)");
  }
  if (settings.timedSteps < 1) throw std::invalid_argument("timed steps: must be >= 1");
  for (const std::string& assignment : settings.options) {
    bool known = false;
    for (const BackendInfo& info : backends) {
      const auto backend = info.create();
      if (!backend->options().has(optionName(assignment))) continue;
      known = true;
      try {
        backend->setOptionFromText(assignment);
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument("backend '" + std::string(info.name) + "': " + error.what());
      }
    }
    if (!known) {
      throw std::invalid_argument("option '" + std::string(optionName(assignment)) +
                                  "': none of the measured backends has it");
    }
  }
}

std::vector<CapacityResult> measureCapacity(
    std::span<const BackendInfo> backends, const CapacitySettings& settings,
    const std::function<void(const CapacityProgress&)>& progress, std::stop_token stop) {
  checkCapacitySettings(backends, settings);
  std::vector<CapacityResult> results;
  for (std::size_t index = 0; index < backends.size() && !stop.stop_requested(); ++index) {
    const BackendInfo& info = backends[index];
    CapacityResult result{std::string(info.name), {}, {}};
    const CostOf medianStep = [&](std::size_t balls) -> std::optional<double> {
      if (stop.stop_requested()) return std::nullopt;
      const Scene scene = standardGas(balls, settings.packingFraction);
      const auto backend = info.create();
      result.options = applyOptions(*backend, settings.options);
      backend->load(scene);
      return medianStepMs(*backend, settings.dt, settings.timedSteps, stop);
    };
    const auto report = [&](const SearchProgress& search) {
      if (!progress) return;
      const double fraction =
          (static_cast<double>(index) + search.fraction) / static_cast<double>(backends.size());
      progress({info.name, index, backends.size(), search, fraction});
    };
    result.outcome = searchCapacity(medianStep, settings.budgetMs, settings.limits, report);
    results.push_back(std::move(result));
  }
  return results;
}

void writeCapacityCsv(std::ostream& out, std::span<const CapacityResult> results) {
  out << kCapacityCsvHeader << '\n';
  for (const CapacityResult& result : results) {
    out << result.backend << ',' << result.outcome.balls << ',' << result.outcome.medianStepMs
        << '\n';
  }
}

}  // namespace fooball::measure
