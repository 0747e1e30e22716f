#include "chosen_backends.h"

namespace fooball::cli {

std::vector<BackendInfo> chosenBackends(const std::vector<std::string>& names) {
  if (names.empty()) return {registeredBackends().begin(), registeredBackends().end()};
  std::vector<BackendInfo> chosen;
  for (const std::string& name : names) {
    createBackend(name);  // throws for an unknown name
    for (const BackendInfo& info : registeredBackends()) {
      if (info.name == name) chosen.push_back(info);
    }
  }
  return chosen;
}

std::vector<RunSpec> chosenRuns(const std::vector<std::string>& specs) {
  std::vector<RunSpec> runs;
  if (specs.empty()) {
    for (const BackendInfo& info : registeredBackends())
      runs.push_back({std::string(info.name), {}});
    return runs;
  }
  for (const std::string& text : specs) {
    runs.push_back(parseRunSpec(text));
    createBackend(runs.back());  // throws for an unknown backend or option
  }
  return runs;
}

}  // namespace fooball::cli
