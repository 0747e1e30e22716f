#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fooball::node_host {

/// Where the Node.js host's files are: backends/js/ (host.js, adapters/, package.json,
/// node_modules/) as the build places it beside the programs, or as `cmake --install` ships it.
/// Looked for, in order: $FOOBALL_NODE_HOST_DIR (for tests and for running from elsewhere);
/// share/fooball/js beside the program's bin/ (installed); the build tree's share/fooball/js,
/// which links to the source tree's backends/js (its path: checkout::kBuildNodeHostDir, from
/// CMake). Empty if none holds host.js.
std::optional<std::filesystem::path> hostDirectory();

/// The `node` program on PATH (Debian's nodejs package installs /usr/bin/node), if any.
std::optional<std::filesystem::path> nodeProgram();

/// Why an engine whose npm package is `package` (a folder of node_modules/) cannot run here, with
/// the fix, e.g. "Node.js not found on PATH (fix: apt install nodejs)"; empty when it can.
std::string unavailableReason(std::string_view package);

}  // namespace fooball::node_host
