#include "host_files.h"

#include <unistd.h>

#include <cstdlib>
#include <system_error>

#include "build_node_host_dir.h"

namespace fooball::node_host {

namespace {

namespace fs = std::filesystem;

bool holdsHost(const fs::path& directory) {
  std::error_code error;
  return fs::is_regular_file(directory / "host.js", error);
}

std::optional<fs::path> programDirectory() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  return self.parent_path();
}

}  // namespace

std::optional<fs::path> hostDirectory() {
  if (const char* chosen = std::getenv("FOOBALL_NODE_HOST_DIR"); chosen != nullptr) {
    if (holdsHost(chosen)) return fs::path(chosen);
    return std::nullopt;  // asked for this one: no other
  }
  if (const std::optional<fs::path> bin = programDirectory()) {
    const fs::path installed = bin->parent_path() / "share" / "fooball" / "js";
    if (holdsHost(installed)) return installed;
  }
  const fs::path built = checkout::kBuildNodeHostDir;
  if (holdsHost(built)) return built;
  return std::nullopt;
}

std::optional<fs::path> nodeProgram() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  const std::string_view directories(path);
  std::size_t start = 0;
  while (start <= directories.size()) {
    const std::size_t end = std::min(directories.find(':', start), directories.size());
    const fs::path directory(directories.substr(start, end - start));
    const fs::path candidate = (directory.empty() ? fs::path(".") : directory) / "node";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

std::string unavailableReason(std::string_view package) {
  if (!nodeProgram()) return "Node.js not found on PATH (fix: apt install nodejs)";
  const std::optional<fs::path> directory = hostDirectory();
  if (!directory) {
    return "the Node.js host's files are missing (fix: reinstall fooball, or set "
           "FOOBALL_NODE_HOST_DIR to a copy of backends/js)";
  }
  std::error_code error;
  const fs::path installed = *directory / "node_modules" / package / "package.json";
  if (!fs::is_regular_file(installed, error)) {
    return "npm package " + std::string(package) + " is not installed (fix: npm ci in " +
           fs::weakly_canonical(*directory, error).string() + ")";
  }
  return {};
}

}  // namespace fooball::node_host
