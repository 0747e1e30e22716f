#include "fooball/cut_short_notice.h"

namespace fooball {

std::string cutShortNotice(const BackendCounters& counters) {
  if (counters.cutShortSteps == 0) return {};
  const std::string steps = counters.cutShortSteps == 1
                                ? std::string("1 step was")
                                : std::to_string(counters.cutShortSteps) + " steps were";
  return steps +
         " cut short (a work cap such as max_events_per_ball, or events looping at one instant): "
         "the rest of each moved without collisions, so the collision counts and the trajectory "
         "are not exact";
}

}  // namespace fooball
