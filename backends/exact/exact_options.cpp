#include "exact_options.h"

namespace fooball::exact {

std::vector<OptionSpec> exactOptionSpecs() {
  const EventLimits defaults;
  return {
      {"rest_bounce_time",
       "s; a wall bounce under gravity returning sooner than this leaves the ball resting on the "
       "wall (drops at most m(g t/2)^2/2 of energy)",
       defaults.restBounceTime, 0.0, 1.0, false},
      {"ball_rest_time",
       "s; a ball slower than |g| t held by walls and sleeping balls falls asleep until a hit that "
       "could lift it out of its pocket, a force or an edit wakes it; pairs feeling different "
       "gravity leave a contact at |dg| t/2 at least (booked: at most m(|g| t)^2 a sleep, "
       "m(|g| t/2)^2/2 a contact; 0: off)",
       defaults.ballRestTime, 0.0, 1.0, false},
      {"max_events_per_ball",
       "events per ball in one step (as for at least 500 balls) before the rest of the step moves "
       "without collisions (0: no cap, every step exact)",
       defaults.maxEventsPerBall, 0.0, 1e9, true, OptionRole::EventCap},
  };
}

EventLimits readEventLimits(const OptionSet& options) {
  EventLimits limits;
  limits.restBounceTime = options.value("rest_bounce_time");
  limits.ballRestTime = options.value("ball_rest_time");
  limits.maxEventsPerBall = options.value("max_events_per_ball");
  return limits;
}

}  // namespace fooball::exact
