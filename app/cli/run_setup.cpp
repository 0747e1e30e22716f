#include "run_setup.h"

#include <cmath>
#include <stdexcept>
#include <system_error>

#include "fooball/number_text.h"
#include "fooball/presets.h"
#include "fooball/scene_file.h"
#include "readable_number.h"
#include "registry.h"
#include "usage_error.h"

namespace fooball::cli {

namespace {

void checkPositiveFinite(double value, const std::string& flag) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw UsageError(flag + ": must be a finite number > 0 (got " + exactNumberText(value) + ")");
  }
}

std::string optionNamesText(const Backend& backend) {
  std::string names;
  for (const OptionSpec& spec : backend.options().specs()) {
    names += (names.empty() ? "" : ", ") + spec.name;
  }
  return names.empty() ? "it has no options" : "its options: " + names;
}

/// Applies "KEY=VALUE", adding which flag and backend it came from to the option's own message.
void applyOption(Backend& backend, const std::string& backendName, const std::string& flagText,
                 const std::string& assignment) {
  try {
    backend.setOptionFromText(assignment);
  } catch (const std::invalid_argument& error) {
    throw UsageError(flagText + ": backend '" + backendName + "': " + error.what());
  }
}

}  // namespace

void checkRunNumbers(const RunOptions& options, bool zeroDurationSteps) {
  if (!(zeroDurationSteps && options.duration == 0.0))
    checkPositiveFinite(options.duration, "--duration");
  if (options.dt) checkPositiveFinite(*options.dt, "--dt");
  if (options.every < 1) {
    throw UsageError("--every: must be a whole number >= 1 (got " + std::to_string(options.every) +
                     ")");
  }
}

std::uint64_t stepCount(double duration, double dt) {
  const double steps = std::round(duration / dt);
  if (steps < 1.0) {
    throw UsageError("--duration " + exactNumberText(duration) +
                     " s is less than half a step (dt " + exactNumberText(dt) + " s)");
  }
  if (steps > static_cast<double>(kMaxRunSteps)) {
    throw UsageError("--duration " + exactNumberText(duration) + " s at dt " + exactNumberText(dt) +
                     " s is " + text::readableText(steps) + " steps, more than the limit of " +
                     std::to_string(kMaxRunSteps));
  }
  return static_cast<std::uint64_t>(steps);
}

RunSpec backendSpec(const RunOptions& options) {
  try {
    return parseRunSpec(options.backendSpec);
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--backend: ") + error.what());
  }
}

std::unique_ptr<Backend> configuredBackend(const RunOptions& options) {
  const RunSpec spec = backendSpec(options);
  std::unique_ptr<Backend> backend = createBackend(spec.backend);
  for (const std::string& assignment : spec.assignments) {
    applyOption(*backend, spec.backend, "--backend " + options.backendSpec, assignment);
  }
  if (options.substeps) {
    const OptionSpec* substeps = backend->options().withRole(OptionRole::Substeps);
    if (substeps == nullptr) {
      throw UsageError("--substeps: backend '" + spec.backend + "' has no substeps option (" +
                       optionNamesText(*backend) + ")");
    }
    applyOption(*backend, spec.backend, "--substeps " + *options.substeps,
                substeps->name + "=" + *options.substeps);
  }
  for (const std::string& assignment : options.assignments) {
    applyOption(*backend, spec.backend, "--option " + assignment, assignment);
  }
  return backend;
}

Scene loadRunScene(const RunOptions& options, std::ostream& warnings) {
  if (!options.scenePath) return loadPreset(options.presetName);
  Scene scene = loadSceneFile(*options.scenePath);
  const std::string warning = savedStateWarning(scene, options.scenePath->string());
  if (!warning.empty()) warnings << "fooball-cli: warning: " << warning << '\n';
  return scene;
}

std::string sceneSource(const RunOptions& options) {
  if (options.scenePath) return options.scenePath->string();
  return "preset '" + options.presetName + "'";
}

std::vector<std::string> changedOptions(const Backend& backend) {
  std::vector<std::string> changed;
  for (const OptionSpec& spec : backend.options().specs()) {
    const double value = backend.options().value(spec.name);
    if (value != spec.defaultValue) changed.push_back(spec.name + "=" + exactNumberText(value));
  }
  return changed;
}

void checkWritableFile(const std::filesystem::path& path, const std::string& flag) {
  const std::string where = flag + " '" + path.string() + "'";
  if (path.empty()) throw UsageError(flag + ": empty file name");
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw UsageError(where + ": is a directory");
  const std::filesystem::path directory =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  if (!std::filesystem::is_directory(directory, ignored)) {
    throw UsageError(where + ": no such directory '" + directory.string() + "'");
  }
}

}  // namespace fooball::cli
