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

}  // namespace fooball::cli
