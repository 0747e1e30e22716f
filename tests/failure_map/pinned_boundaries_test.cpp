// The failure map's boundaries, pinned per sweep and backend (docs/accuracy.md), so a change
// that moves one is noticed. What each backend must do on each sweep is its row in
// tests/backend_profiles.cpp: where the method fixes the boundary (tunnelling, the cradle, the
// exact solver, double-precision collision rules) the bracket is derived from it and the
// derivation is in the comment there; where only a run can tell (dense packing, the pile) the
// row pins the grid cell the current code lands in, and says so. The grids are the `--quick`
// ones except for tunnelling, which is cheap at full resolution. Every registered backend is run
// on every sweep, once, and must pin something of each.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "backend_profiles.h"
#include "boundary.h"
#include "failure_map.h"
#include "registry.h"

namespace {

using fooball::BackendInfo;
using fooball::registeredBackends;
using fooball::failure_map::Boundary;
using fooball::failure_map::findSweep;
using fooball::failure_map::locateBoundaries;
using fooball::failure_map::runSweep;
using fooball::failure_map::SweepPoint;
using fooball::failure_map::SweepSpec;
using fooball::failure_map::sweepSpecs;
using fooball::testing::BoundaryExpectation;
using fooball::testing::Interval;
using fooball::testing::profileFor;

/// One backend on one sweep.
struct BackendSweep {
  BackendInfo backend;
  std::string_view sweep;
};

void PrintTo(const BackendSweep& param, std::ostream* out) {
  *out << param.backend.name << " on " << param.sweep;
}

std::vector<BackendSweep> everyBackendOnEverySweep() {
  std::vector<BackendSweep> cases;
  for (const BackendInfo& backend : registeredBackends()) {
    for (const SweepSpec& spec : sweepSpecs())
      cases.push_back({backend, spec.name});
  }
  return cases;
}

std::string backendName(const ::testing::TestParamInfo<BackendInfo>& param) {
  return std::string(param.param.name);
}

/// "elastic_mass_ratio".
std::string caseName(const ::testing::TestParamInfo<BackendSweep>& info) {
  std::string name = std::string(info.param.backend.name) + "_" + std::string(info.param.sweep);
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

std::string describe(const SweepPoint& point) {
  std::ostringstream out;
  out << point.variant << " at " << point.parameter << ": error " << point.error << ", overlap "
      << point.maxOverlap;
  return out.str();
}

void expectWithin(const std::optional<double>& value, const Interval& interval, const char* what) {
  ASSERT_TRUE(value.has_value()) << "the curve has no " << what;
  EXPECT_TRUE(interval.contains(*value)) << what << " at " << *value << ", pinned in ["
                                         << interval.low << ", " << interval.high << "]";
}

void expectMatches(const BoundaryExpectation& expected, const SweepSpec& spec,
                   const std::vector<SweepPoint>& sweep) {
  std::vector<SweepPoint> points;
  for (const SweepPoint& point : sweep) {
    if (expected.variant.empty() || point.variant == expected.variant) points.push_back(point);
  }
  ASSERT_FALSE(points.empty()) << "no curve '" << expected.variant << "'";
  for (const SweepPoint& point : points) {
    if (std::isfinite(expected.maxError)) {
      EXPECT_LT(point.error, expected.maxError) << describe(point);
    }
    if (expected.passesEverywhere) {
      EXPECT_TRUE(point.passed) << describe(point);
    }
    if (expected.passesBelow && point.parameter < *expected.passesBelow) {
      EXPECT_TRUE(point.passed) << describe(point);
    }
    if (expected.passesAbove && point.parameter > *expected.passesAbove) {
      EXPECT_TRUE(point.passed) << describe(point);
    }
    if (expected.failsAbove && point.parameter > *expected.failsAbove) {
      EXPECT_FALSE(point.passed) << describe(point);
    }
    if (expected.errorFloor && point.parameter <= expected.errorFloor->atOrBelow) {
      EXPECT_GT(point.error, expected.errorFloor->error) << describe(point);
    }
  }
  if (expected.lastPass || expected.firstFail) {
    ASSERT_FALSE(expected.variant.empty()) << "a boundary is pinned per curve: name its variant";
    const std::vector<Boundary> boundaries = locateBoundaries(spec, points);
    ASSERT_EQ(boundaries.size(), 1u);
    if (expected.lastPass)
      expectWithin(boundaries.front().lastPass, *expected.lastPass, "last pass");
    if (expected.firstFail)
      expectWithin(boundaries.front().firstFail, *expected.firstFail, "first fail");
  }
}

class PinnedBoundaries : public ::testing::TestWithParam<BackendSweep> {};

TEST_P(PinnedBoundaries, AreWhereTheBackendsProfileSays) {
  const std::string_view backend = GetParam().backend.name;
  const SweepSpec& spec = findSweep(GetParam().sweep);
  const fooball::testing::BackendProfile& profile = profileFor(backend);
  const bool quick = spec.name != "tunnelling";
  const std::vector<SweepPoint> sweep = runSweep(spec, backend, quick);
  int pinned = 0;
  for (const BoundaryExpectation& expected : profile.failureMap) {
    if (expected.sweep != spec.name) continue;
    ++pinned;
    SCOPED_TRACE(std::string(backend) + " " + std::string(spec.name) + " '" +
                 std::string(expected.variant) + "'");
    expectMatches(expected, spec, sweep);
  }
  EXPECT_GT(pinned, 0) << "backend '" << backend << "' pins nothing of sweep '" << spec.name
                       << "': state where it fails in its row of tests/backend_profiles.cpp";
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, PinnedBoundaries,
                         ::testing::ValuesIn(everyBackendOnEverySweep()), caseName);

class PinnedSweeps : public ::testing::TestWithParam<BackendInfo> {};

TEST_P(PinnedSweeps, AreSweepsOfTheFailureMap) {
  for (const BoundaryExpectation& expected : profileFor(GetParam().name).failureMap)
    EXPECT_NO_THROW(findSweep(expected.sweep)) << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, PinnedSweeps, ::testing::ValuesIn(registeredBackends()),
                         backendName);

}  // namespace
