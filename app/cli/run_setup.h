#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "fooball/backend.h"
#include "fooball/run_spec.h"
#include "fooball/scene.h"
#include "run_options.h"

namespace fooball::cli {

/// Checks --duration, --dt and --every on their own (finite, positive, ≥ 1); throws UsageError.
/// With `zeroDurationSteps` (run), --duration 0 is allowed too: it steps nothing.
void checkRunNumbers(const RunOptions& options, bool zeroDurationSteps = false);

/// round(duration / dt), checked to be in [1, kMaxRunSteps]; throws UsageError.
std::uint64_t stepCount(double duration, double dt);

/// --backend's run spec as parsed; throws UsageError naming the flag and what is wrong with the
/// spec's form.
RunSpec backendSpec(const RunOptions& options);

/// The backend --backend names, with the spec's options, then --substeps, then every --option
/// applied, in that order (a later one wins): the flags are shorthand that edit the spec. Throws
/// UsageError naming the flag, the backend and (for an unknown option) its options;
/// std::invalid_argument listing the known backends for an unknown name.
std::unique_ptr<Backend> configuredBackend(const RunOptions& options);

/// The scene of --scene or --preset; throws SceneError naming the file or preset and the place.
/// A file saved from a running simulation that breaks a hand-written scene's rules loads, and
/// its warning (savedStateWarning) goes to `warnings` as "fooball-cli: warning: …".
Scene loadRunScene(const RunOptions& options, std::ostream& warnings);

/// How the summary names where the scene came from: the file path or "preset 'NAME'".
std::string sceneSource(const RunOptions& options);

/// "KEY=VALUE" for every option of `backend` that is not at its default.
std::vector<std::string> changedOptions(const Backend& backend);

/// Throws UsageError unless `path` could be created: a file name in an existing directory.
/// Lets --save fail before the run instead of after it.
void checkWritableFile(const std::filesystem::path& path, const std::string& flag);

}  // namespace fooball::cli
