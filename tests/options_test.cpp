// OptionSet: the named backend knobs. Backends trust the values it holds, so every bad input
// must be refused with a message naming the option and the reason, and leave the value as it was.

#include "fooball/options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace fooball {
namespace {

using ::testing::HasSubstr;

OptionSet sampleOptions() {
  return OptionSet({
      {"substeps", "solver substeps per step", 4.0, 1.0, 1000.0, true},
      {"tolerance", "relative, of the step", 0.25, 0.0, 1.0, false},
      {"warm_start", "reuse impulses, 0 or 1", 1.0, 0.0, 1.0, true},
  });
}

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

void expectUnchanged(const OptionSet& options) {
  EXPECT_EQ(options.value("substeps"), 4.0);
  EXPECT_EQ(options.value("tolerance"), 0.25);
  EXPECT_EQ(options.value("warm_start"), 1.0);
}

TEST(OptionSet, StartsAtTheDefaultsAndKeepsTheSpecsInOrder) {
  const OptionSet options = sampleOptions();
  expectUnchanged(options);
  ASSERT_EQ(options.specs().size(), 3u);
  EXPECT_EQ(options.specs()[0].name, "substeps");
  EXPECT_EQ(options.specs()[1].name, "tolerance");
  EXPECT_EQ(options.specs()[2].name, "warm_start");
  EXPECT_TRUE(options.specs()[0].integer);
  EXPECT_FALSE(options.specs()[1].integer);
}

TEST(OptionSet, SetsValuesInRangeIncludingTheBounds) {
  OptionSet options = sampleOptions();
  options.set("substeps", 8.0);
  EXPECT_EQ(options.value("substeps"), 8.0);
  options.set("substeps", 1.0);
  EXPECT_EQ(options.value("substeps"), 1.0);
  options.set("substeps", 1000.0);
  EXPECT_EQ(options.value("substeps"), 1000.0);
  options.set("tolerance", 0.0);
  EXPECT_EQ(options.value("tolerance"), 0.0);
  options.set("tolerance", 0.625);
  EXPECT_EQ(options.value("tolerance"), 0.625) << "real options take fractions";
  options.set("warm_start", 0.0);
  EXPECT_EQ(options.value("warm_start"), 0.0);
}

TEST(OptionSet, RejectsUnknownNamesListingTheKnownOnes) {
  OptionSet options = sampleOptions();
  const std::string message = errorOf([&] { options.set("substep", 3.0); });
  EXPECT_THAT(message, HasSubstr("substep'"));
  EXPECT_THAT(message, HasSubstr("unknown"));
  EXPECT_THAT(message, HasSubstr("substeps"));
  EXPECT_THAT(message, HasSubstr("tolerance"));
  EXPECT_THAT(message, HasSubstr("warm_start"));
  EXPECT_THROW((void)options.value("nope"), std::invalid_argument);
  expectUnchanged(options);

  OptionSet none({});
  EXPECT_THAT(errorOf([&] { none.set("substeps", 1.0); }), HasSubstr("none"));
}

TEST(OptionSet, RejectsValuesOutOfRange) {
  OptionSet options = sampleOptions();
  const std::string message = errorOf([&] { options.set("substeps", 1001.0); });
  EXPECT_THAT(message, HasSubstr("substeps"));
  EXPECT_THAT(message, HasSubstr("1000"));
  EXPECT_THAT(message, HasSubstr("1001"));
  EXPECT_THROW(options.set("substeps", 0.0), std::invalid_argument);
  EXPECT_THROW(options.set("substeps", -4.0), std::invalid_argument);
  EXPECT_THROW(options.set("tolerance", -1e-300), std::invalid_argument);
  EXPECT_THROW(options.set("tolerance", 1.0000001), std::invalid_argument);
  EXPECT_THROW(options.set("warm_start", 2.0), std::invalid_argument);
  expectUnchanged(options);
}

TEST(OptionSet, RejectsFractionsForIntegerOptions) {
  OptionSet options = sampleOptions();
  const std::string message = errorOf([&] { options.set("substeps", 2.5); });
  EXPECT_THAT(message, HasSubstr("substeps"));
  EXPECT_THAT(message, HasSubstr("whole"));
  EXPECT_THAT(message, HasSubstr("2.5"));
  EXPECT_THROW(options.set("warm_start", 0.5), std::invalid_argument);
  EXPECT_THROW(options.set("substeps", 4.000000001), std::invalid_argument);
  expectUnchanged(options);
}

TEST(OptionSet, RejectsNaNAndInfinity) {
  OptionSet options = sampleOptions();
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    EXPECT_THAT(errorOf([&] { options.set("tolerance", bad); }), HasSubstr("tolerance"));
    EXPECT_THROW(options.set("substeps", bad), std::invalid_argument);
  }
  expectUnchanged(options);
}

TEST(OptionSet, SetFromTextParsesNumbers) {
  OptionSet options = sampleOptions();
  options.setFromText("substeps=12");
  EXPECT_EQ(options.value("substeps"), 12.0);
  options.setFromText("tolerance=0.125");
  EXPECT_EQ(options.value("tolerance"), 0.125);
  options.setFromText("tolerance=5e-2");
  EXPECT_EQ(options.value("tolerance"), 5e-2);
  options.setFromText("substeps=1e2");
  EXPECT_EQ(options.value("substeps"), 100.0);
}

TEST(OptionSet, SetFromTextTakesTrueFalseOnOffForSwitches) {
  OptionSet options = sampleOptions();
  options.setFromText("warm_start=false");
  EXPECT_EQ(options.value("warm_start"), 0.0);
  options.setFromText("warm_start=true");
  EXPECT_EQ(options.value("warm_start"), 1.0);
  options.setFromText("warm_start=off");
  EXPECT_EQ(options.value("warm_start"), 0.0);
  options.setFromText("warm_start=on");
  EXPECT_EQ(options.value("warm_start"), 1.0);
  options.setFromText("warm_start=0");
  EXPECT_EQ(options.value("warm_start"), 0.0);
  // Only 0/1 integer options are switches: "true" is not a substep count.
  EXPECT_THROW(options.setFromText("substeps=true"), std::invalid_argument);
  EXPECT_THROW(options.setFromText("tolerance=on"), std::invalid_argument);
}

TEST(OptionSet, SetFromTextTakesANamedChoiceByItsName) {
  // An engine's releases, e.g. rapier's `version`: the value is the index of the name.
  OptionSet options(
      {{"version", "release", 0.0, 0.0, 1.0, true, OptionRole::Other, {"0.21.0", "0.19.3"}}});
  options.setFromText("version=0.19.3");
  EXPECT_EQ(options.value("version"), 1.0);
  options.setFromText("version=0.21.0");
  EXPECT_EQ(options.value("version"), 0.0);
  EXPECT_THAT(errorOf([&] { options.setFromText("version=0.18.0"); }),
              HasSubstr("'0.18.0' is not one of 0.21.0, 0.19.3"));
  options.setFromText("version=1");  // the index, as saved files write it
  EXPECT_EQ(options.value("version"), 1.0);
}

TEST(OptionSet, SetFromTextRejectsMalformedAssignments) {
  OptionSet options = sampleOptions();
  for (const char* bad :
       {"x=", "=3", "3", "", "=", "substeps", "substeps=", "substeps=abc", "substeps=4x",
        "substeps= 4", "substeps=4 ", "substeps=0x10", "substeps=nan", "substeps=inf",
        "tolerance=-inf", "substeps=2.5", "substeps=0", "tolerance=2"}) {
    EXPECT_THROW(options.setFromText(bad), std::invalid_argument) << "'" << bad << "'";
  }
  EXPECT_THAT(errorOf([&] { options.setFromText("substeps=4x"); }), HasSubstr("'4x'"));
  EXPECT_THAT(errorOf([&] { options.setFromText("substeps=abc"); }), HasSubstr("substeps"));
  EXPECT_THAT(errorOf([&] { options.setFromText("3"); }), HasSubstr("KEY=VALUE"));
  EXPECT_THAT(errorOf([&] { options.setFromText("x="); }), HasSubstr("substeps"))
      << "an unknown key lists the known ones";
  expectUnchanged(options);
}

}  // namespace
}  // namespace fooball
