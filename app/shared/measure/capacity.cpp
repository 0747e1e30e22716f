#include "capacity.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "fooball/standard_scenes.h"

namespace fooball::measure {

namespace {

/// s: a minute of simulated warm-up is 3'600 steps at 60 Hz, far past any thermalisation.
constexpr double kMaxWarmUpSeconds = 60.0;

std::string_view optionName(std::string_view assignment) {
  return assignment.substr(0, assignment.find('='));
}

/// A run spec with several options has commas ("box2d:substeps=8,velocity_iterations=20"): such
/// a field is quoted as RFC 4180 says, so every row keeps its three columns.
void writeCsvField(std::ostream& out, std::string_view text) {
  if (text.find_first_of(",\"\n") == std::string_view::npos) {
    out << text;
    return;
  }
  out << '"';
  for (const char c : text) {
    if (c == '"') out << '"';
    out << c;
  }
  out << '"';
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

std::vector<RunSpec> defaultRuns(std::span<const BackendInfo> backends) {
  std::vector<RunSpec> runs;
  for (const BackendInfo& info : backends)
    runs.push_back({std::string(info.name), {}});
  return runs;
}

void checkCapacitySettings(std::span<const RunSpec> runs, const CapacitySettings& settings) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (!positive(settings.budgetMs)) throw std::invalid_argument("budget: must be a number > 0");
  if (!positive(settings.dt)) throw std::invalid_argument("dt: must be a number > 0");
  if (!(settings.packingFraction > 0.0 && settings.packingFraction < 0.9)) {
    throw std::invalid_argument("packing fraction: must be in (0, 0.9)");
  }
  if (settings.timedSteps < 1) throw std::invalid_argument("timed steps: must be >= 1");
  if (!(settings.warmUpSeconds >= 0.0 && settings.warmUpSeconds <= kMaxWarmUpSeconds)) {
    throw std::invalid_argument("warm-up: must be a number of seconds in [0, 60]");
  }
  for (const RunSpec& run : runs)
    createBackend(run);  // throws naming the spec
  for (const std::string& assignment : settings.options) {
    bool known = false;
    for (const RunSpec& run : runs) {
      const auto backend = createBackend(run.backend);
      if (!backend->options().has(optionName(assignment))) continue;
      known = true;
      try {
        backend->setOptionFromText(assignment);
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument("backend '" + run.backend + "': " + error.what());
      }
    }
    if (!known) {
      throw std::invalid_argument("option '" + std::string(optionName(assignment)) +
                                  "': none of the measured backends has it");
    }
  }
}

StepTiming stepTimingOf(const CapacitySettings& settings) {
  StepTiming timing;
  timing.dt = settings.dt;
  // − 1e-9: 1 s / (1/60 s) is 60.000000000000004 in doubles, which is 60 steps, not 61.
  const double warmUpSteps = std::ceil(settings.warmUpSeconds / settings.dt - 1e-9);
  timing.warmUpSteps = static_cast<int>(std::clamp(warmUpSteps, 1.0, 1e7));
  timing.timedSteps = settings.timedSteps;
  timing.giveUpAboveMs = 10.0 * settings.budgetMs;
  return timing;
}

std::vector<CapacityResult> measureCapacity(
    std::span<const RunSpec> runs, const CapacitySettings& settings,
    const std::function<void(const CapacityProgress&)>& progress, std::stop_token stop) {
  checkCapacitySettings(runs, settings);
  const StepTiming timing = stepTimingOf(settings);
  std::vector<CapacityResult> results;
  for (std::size_t index = 0; index < runs.size() && !stop.stop_requested(); ++index) {
    const RunSpec& run = runs[index];
    CapacityResult result{run.text(), {}, {}};
    const CostOf medianStep = [&](std::size_t balls) -> std::optional<double> {
      if (stop.stop_requested()) return std::nullopt;
      const Scene scene = standardGas(balls, settings.packingFraction);
      const auto backend = createBackend(run.backend);
      result.options = applyOptions(*backend, settings.options);
      for (const std::string& assignment : run.assignments)
        backend->setOptionFromText(assignment);
      backend->load(scene);
      return medianStepMs(*backend, timing, stop);
    };
    const auto report = [&](const SearchProgress& search) {
      if (!progress) return;
      const double fraction =
          (static_cast<double>(index) + search.fraction) / static_cast<double>(runs.size());
      progress({result.backend, index, runs.size(), search, fraction});
    };
    result.outcome = searchCapacity(medianStep, settings.budgetMs, settings.limits, report);
    results.push_back(std::move(result));
  }
  return results;
}

void writeCapacityCsv(std::ostream& out, std::span<const CapacityResult> results) {
  out << kCapacityCsvHeader << '\n';
  for (const CapacityResult& result : results) {
    writeCsvField(out, result.backend);
    out << ',' << result.outcome.balls << ',' << result.outcome.medianStepMs << '\n';
  }
}

std::string capacityNote(const CapacityResult& result) {
  const std::string_view name =
      std::string_view(result.backend).substr(0, result.backend.find(':'));
  const std::string_view runtime = backendInfo(name).runtime;
  std::string note = runtime.empty() ? "" : std::string(runtime) + " in Node.js";
  const auto add = [&note](std::string_view text) {
    note += (note.empty() ? "" : "; ") + std::string(text);
  };
  const SearchOutcome& outcome = result.outcome;
  if (outcome.reachedMaxBalls) add("the scene format's limit: capacity is higher");
  if (outcome.timedOut) add("time limit: best count so far");
  if (outcome.cancelled) add("cancelled");
  return note;
}

}  // namespace fooball::measure
