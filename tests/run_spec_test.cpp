// RunSpec: the text that names a run's method (DESIGN.md, "Runs, run specs and run groups"), and
// the registry's factory that makes the backend it names. A spec is also the run's label in the
// CLI's CSV and the GUI's legend, so its text must read back as the same spec, and every error
// must name the spec it came from.

#include "fooball/run_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "registry.h"

namespace fooball {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

/// The message of the std::invalid_argument `action` throws; a test failure if it throws none.
template <class Action>
std::string errorOf(Action&& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "no std::invalid_argument was thrown";
  return {};
}

/// A value of `option` in its range that is not its default: the middle of the range, rounded
/// for whole-number options.
double nonDefaultValue(const OptionSpec& option) {
  double value = option.min + 0.5 * (option.max - option.min);
  if (option.integer) value = std::floor(value);
  if (value == option.defaultValue)
    value = option.defaultValue == option.min ? option.max : option.min;
  return value;
}

TEST(RunSpec, ParsesNameAndAssignmentsInOrder) {
  const RunSpec spec = parseRunSpec("box2d:substeps=8,velocity_iterations=20");
  EXPECT_EQ(spec.backend, "box2d");
  EXPECT_EQ(spec.assignments, (std::vector<std::string>{"substeps=8", "velocity_iterations=20"}));

  const RunSpec bare = parseRunSpec("elastic");
  EXPECT_EQ(bare.backend, "elastic");
  EXPECT_TRUE(bare.assignments.empty());
}

TEST(RunSpec, TextReadsBackAsTheSameSpec) {
  for (const char* text :
       {"elastic", "elastic:substeps=16", "box2d:substeps=8,velocity_iterations=20",
        "exact:rest_bounce_time=1e-07,max_events_per_ball=50"}) {
    SCOPED_TRACE(text);
    const RunSpec spec = parseRunSpec(text);
    EXPECT_EQ(spec.text(), text);
    EXPECT_EQ(parseRunSpec(spec.text()), spec);
  }
}

TEST(RunSpec, SetReplacesAnEarlierAssignmentInPlaceAndAppendsANewOne) {
  RunSpec spec = parseRunSpec("box2d:substeps=8,velocity_iterations=20");
  spec.set("substeps", 16.0);
  EXPECT_EQ(spec.text(), "box2d:substeps=16,velocity_iterations=20");
  spec.set("position_iterations", 0.1);  // shortest round-trip text, not "0.100000"
  EXPECT_EQ(spec.text(), "box2d:substeps=16,velocity_iterations=20,position_iterations=0.1");
  spec.set("velocity_iterations", 3.0);
  EXPECT_EQ(spec.text(), "box2d:substeps=16,velocity_iterations=3,position_iterations=0.1");

  RunSpec bare = parseRunSpec("elastic");
  bare.set("substeps", 2.0);
  EXPECT_EQ(bare.text(), "elastic:substeps=2");
}

TEST(RunSpec, MalformedSpecsThrowNamingTheSpec) {
  for (const char* text : {"", ":substeps=1", "elastic:", "elastic:substeps", "elastic:=4",
                           "elastic:substeps=", "elastic:substeps=1,", "elastic:substeps=1,,x=2",
                           "elastic:,substeps=1"}) {
    SCOPED_TRACE(text);
    EXPECT_THAT(errorOf([&] { parseRunSpec(text); }),
                StartsWith("run spec '" + std::string(text) + "': "));
  }
}

TEST(RunSpec, AnOptionSetTwiceThrowsNamingTheSpecAndTheOption) {
  const std::string text = "elastic:substeps=1,threads=2,substeps=2";
  EXPECT_THAT(
      errorOf([&] { parseRunSpec(text); }),
      AllOf(StartsWith("run spec '" + text + "': "), HasSubstr("'substeps'"), HasSubstr("twice")));
}

TEST(RunSpec, CreateBackendAppliesEveryOptionOfEveryBackend) {
  for (const BackendInfo& info : registeredBackends()) {
    RunSpec spec{std::string(info.name), {}};
    const std::unique_ptr<Backend> defaults = info.create();
    for (const OptionSpec& option : defaults->options().specs())
      spec.set(option.name, nonDefaultValue(option));
    SCOPED_TRACE(spec.text());
    const std::unique_ptr<Backend> backend = createBackend(spec);
    ASSERT_NE(backend, nullptr);
    for (const OptionSpec& option : backend->options().specs()) {
      SCOPED_TRACE(option.name);
      EXPECT_EQ(backend->options().value(option.name), nonDefaultValue(option));
      EXPECT_NE(backend->options().value(option.name), option.defaultValue);
    }
  }
}

TEST(RunSpec, CreateBackendWithoutOptionsHasTheDefaults) {
  for (const BackendInfo& info : registeredBackends()) {
    SCOPED_TRACE(info.name);
    const std::unique_ptr<Backend> backend = createBackend(RunSpec{std::string(info.name), {}});
    for (const OptionSpec& option : backend->options().specs())
      EXPECT_EQ(backend->options().value(option.name), option.defaultValue) << option.name;
  }
}

TEST(RunSpec, CreateBackendNamesTheSpecAndTheReason) {
  // An unknown backend: the known ones are listed.
  EXPECT_THAT(errorOf([] { createBackend(parseRunSpec("warp-drive:substeps=2")); }),
              AllOf(StartsWith("run spec 'warp-drive:substeps=2': "), HasSubstr("unknown backend"),
                    HasSubstr(std::string(registeredBackends().front().name))));

  for (const BackendInfo& info : registeredBackends()) {
    const std::string name(info.name);
    SCOPED_TRACE(name);
    const std::string unknown = name + ":warp_factor=9";
    EXPECT_THAT(errorOf([&] { createBackend(parseRunSpec(unknown)); }),
                AllOf(StartsWith("run spec '" + unknown + "': "), HasSubstr("'warp_factor'")));
    const std::unique_ptr<Backend> backend = info.create();
    if (backend->options().specs().empty()) continue;
    const OptionSpec& option = backend->options().specs().front();
    for (const std::string value : {"1e300", "-1e300", "many", "nan"}) {
      const std::string text = name + ":" + option.name + "=" + value;
      SCOPED_TRACE(text);
      EXPECT_THAT(errorOf([&] { createBackend(parseRunSpec(text)); }),
                  AllOf(StartsWith("run spec '" + text + "': "), HasSubstr(option.name)));
    }
  }
}

}  // namespace
}  // namespace fooball
