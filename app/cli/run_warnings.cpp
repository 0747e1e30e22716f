#include "run_warnings.h"

#include <string>

#include "fooball/cut_short_notice.h"
#include "fooball/limit_check.h"
#include "registry.h"

namespace fooball::cli {

void printRunWarnings(const Simulation& run, std::string_view backendName,
                      std::string_view runLabel, std::ostream& err) {
  const std::string prefix =
      "fooball-cli: warning: " +
      (runLabel.empty() ? std::string() : "run " + std::string(runLabel) + ": ");
  if (const std::string notice = cutShortNotice(run.counters()); !notice.empty())
    err << prefix << notice << '\n';
  if (run.steps() == 0) return;  // --duration 0 only checks the scene: no method has run
  const MethodLimits& limits = backendInfo(backendName).limits;
  if (const std::string notice = methodLimitNotice(crossedLimits(run, limits)); !notice.empty())
    err << prefix << notice << '\n';
}

}  // namespace fooball::cli
