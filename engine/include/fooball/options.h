#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fooball {

/// What a knob means to the tools that vary it, so none of them matches options by name.
enum class OptionRole {
  Other,
  Substeps,    ///< solver steps per simulation step: the trade-off grid's accuracy axis
  Iterations,  ///< solver iterations per solver step: the trade-off grid's second axis
  Threads,     ///< worker threads; results are identical for any count (runs share the cores)
  /// Balls each worker thread needs before it joins a step (0: every thread, always). Like
  /// Threads it changes the speed only, never the results.
  BallsPerThread,
  /// A cap on the work of one step that cuts the step short when reached (0: no cap, the
  /// default); cut-short steps are counted (BackendCounters::cutShortSteps).
  EventCap,
};

/// Events per ball in one step that tools which must finish (the failure map, the random suite)
/// allow where an OptionRole::EventCap option is at its default, no cap: a pile resting on
/// balls under gravity is a Zeno sequence of ever shorter bounces with no finite end, so an
/// uncapped event-driven step there never ends. The exact solver's default before the cap
/// became opt-in, so the measured findings and work caps stay as they were.
inline constexpr double kFinishingEventsPerBall = 200.0;

/// One named backend knob (substeps, Box2D iterations, …).
struct OptionSpec {
  std::string name;         ///< e.g. "substeps"
  std::string description;  ///< one line, with the unit
  double defaultValue = 0.0;
  double min = 0.0;
  double max = 0.0;
  bool integer = false;  ///< whole numbers only (counts); booleans are integers in [0, 1]
  OptionRole role = OptionRole::Other;
  /// Named values, e.g. an engine's releases {"0.21.0", "0.19.3"}: the option's value is an index
  /// into them (an integer in [0, size − 1]), and KEY=NAME sets it by name (KEY=INDEX too, as
  /// saved files and tools write it). Empty: a number.
  std::vector<std::string> choices = {};
};

/// The values of a backend's options. Checks names and ranges, so backends can trust values.
class OptionSet {
 public:
  explicit OptionSet(std::vector<OptionSpec> specs);

  std::span<const OptionSpec> specs() const { return specs_; }
  bool has(std::string_view name) const;
  double value(std::string_view name) const;
  /// The option playing `role`, if this backend has one.
  const OptionSpec* withRole(OptionRole role) const;

  /// Throws std::invalid_argument naming the option and the reason (unknown name, out of range,
  /// not a whole number, not finite).
  void set(std::string_view name, double value);

  /// Parses "KEY=VALUE" ("true"/"false"/"on"/"off" allowed for 0/1 options) and sets it.
  void setFromText(std::string_view assignment);

 private:
  std::size_t indexOf(std::string_view name) const;

  std::vector<OptionSpec> specs_;
  std::vector<double> values_;
};

}  // namespace fooball
