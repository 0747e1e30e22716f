// locateBoundaries: how a curve of judged points becomes "passes up to X, fails from Y".

#include "boundary.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "failure_map.h"

namespace {

using fooball::failure_map::Boundary;
using fooball::failure_map::findSweep;
using fooball::failure_map::locateBoundaries;
using fooball::failure_map::SweepPoint;
using fooball::failure_map::SweepSpec;

SweepPoint judged(std::string backend, double parameter, bool passed) {
  SweepPoint point;
  point.sweep = "test";
  point.backend = std::move(backend);
  point.parameter = parameter;
  point.passed = passed;
  return point;
}

SweepSpec spec(bool harderAbove) {
  SweepSpec spec;
  spec.name = "test";
  spec.harderAbove = harderAbove;
  return spec;
}

TEST(Boundary, IsTheFirstFailureWalkingFromTheEasyEndInAnyOrder) {
  const std::vector<SweepPoint> points = {judged("a", 4.0, false), judged("a", 1.0, true),
                                          judged("a", 2.0, true), judged("a", 8.0, false)};
  const std::vector<Boundary> boundaries = locateBoundaries(spec(true), points);
  ASSERT_EQ(boundaries.size(), 1u);
  EXPECT_EQ(boundaries[0].lastPass, 2.0);
  EXPECT_EQ(boundaries[0].firstFail, 4.0);
  EXPECT_FALSE(boundaries[0].passesAgain);
}

TEST(Boundary, WalksDownwardsWhenSmallerParametersAreHarder) {
  const std::vector<SweepPoint> points = {judged("a", 1.0, true), judged("a", 0.1, true),
                                          judged("a", 0.01, false)};
  const std::vector<Boundary> boundaries = locateBoundaries(spec(false), points);
  ASSERT_EQ(boundaries.size(), 1u);
  EXPECT_EQ(boundaries[0].lastPass, 0.1);
  EXPECT_EQ(boundaries[0].firstFail, 0.01);
}

TEST(Boundary, ReportsAPassAfterTheFirstFailure) {
  const std::vector<SweepPoint> points = {judged("a", 1.0, true), judged("a", 2.0, false),
                                          judged("a", 3.0, true)};
  const std::vector<Boundary> boundaries = locateBoundaries(spec(true), points);
  ASSERT_EQ(boundaries.size(), 1u);
  EXPECT_EQ(boundaries[0].firstFail, 2.0);
  EXPECT_TRUE(boundaries[0].passesAgain);
}

TEST(Boundary, KeepsEveryCurveApartAndSaysWhenOneNeverFailsOrAlwaysFails) {
  const std::vector<SweepPoint> points = {judged("a", 1.0, true), judged("b", 1.0, false),
                                          judged("a", 2.0, true), judged("b", 2.0, false)};
  const std::vector<Boundary> boundaries = locateBoundaries(spec(true), points);
  ASSERT_EQ(boundaries.size(), 2u);
  EXPECT_EQ(boundaries[0].backend, "a");
  EXPECT_EQ(boundaries[0].lastPass, 2.0);
  EXPECT_FALSE(boundaries[0].firstFail);
  EXPECT_EQ(boundaries[1].backend, "b");
  EXPECT_FALSE(boundaries[1].lastPass);
  EXPECT_EQ(boundaries[1].firstFail, 1.0);
}

TEST(SweepSpecs, AreFoundByNameAndAnUnknownNameListsTheKnownOnes) {
  EXPECT_EQ(findSweep("cradle").name, "cradle");
  try {
    findSweep("tunneling");
    FAIL() << "no error for an unknown sweep";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "--sweep: unknown sweep 'tunneling' (known: tunnelling, mass-ratio, cradle, "
              "packing, scale, pile)");
  }
}

TEST(SweepSpecs, HoldNoCommasInTheTextsTheCsvWrites) {
  for (const SweepSpec& spec : fooball::failure_map::sweepSpecs()) {
    EXPECT_EQ(spec.parameterName.find(','), std::string_view::npos) << spec.name;
    EXPECT_EQ(spec.errorName.find(','), std::string_view::npos) << spec.name;
  }
}

}  // namespace
