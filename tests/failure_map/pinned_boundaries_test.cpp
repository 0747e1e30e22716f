// The failure map's boundaries, pinned per sweep and backend (docs/accuracy.md), so a change
// that moves one is noticed. Where the method fixes the boundary (tunnelling, the cradle, the
// exact solver, double-precision collision rules) the bracket is derived from it and the
// derivation is in the comment; where only a run can tell (dense packing, the pile) the test
// pins the grid cell the current code lands in, and says so. The grids are the `--quick` ones
// except for tunnelling, which is cheap at full resolution.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "boundary.h"
#include "failure_map.h"

namespace {

using fooball::failure_map::Boundary;
using fooball::failure_map::findSweep;
using fooball::failure_map::locateBoundaries;
using fooball::failure_map::runSweep;
using fooball::failure_map::SweepPoint;

/// Double rounding over a few hundred operations on O(1) values; the exact collision rules
/// (closed-form impulses, exact event times) leave nothing else.
constexpr double kDoubleRounding = 1e-12;

/// Each sweep runs once per backend for the whole suite.
const std::vector<SweepPoint>& sweep(const std::string& name, const std::string& backend) {
  static std::map<std::pair<std::string, std::string>, std::vector<SweepPoint>> runs;
  const auto key = std::make_pair(name, backend);
  auto found = runs.find(key);
  if (found == runs.end()) {
    const bool quick = name != "tunnelling";
    found = runs.emplace(key, runSweep(findSweep(name), backend, quick)).first;
  }
  return found->second;
}

std::vector<SweepPoint> curve(const std::string& name, const std::string& backend,
                              const std::string& variant) {
  std::vector<SweepPoint> points;
  for (const SweepPoint& point : sweep(name, backend)) {
    if (point.variant == variant) points.push_back(point);
  }
  EXPECT_FALSE(points.empty()) << name << " " << backend << " has no curve '" << variant << "'";
  return points;
}

Boundary boundaryOf(const std::string& name, const std::string& backend,
                    const std::string& variant) {
  const std::vector<SweepPoint> points = curve(name, backend, variant);
  const std::vector<Boundary> boundaries = locateBoundaries(findSweep(name), points);
  return boundaries.empty() ? Boundary{} : boundaries.front();
}

void expectPassesEverywhere(const std::string& name, const std::string& backend) {
  for (const SweepPoint& point : sweep(name, backend)) {
    EXPECT_TRUE(point.passed) << name << " " << backend << " " << point.variant << " at "
                              << point.parameter << ": error " << point.error << ", overlap "
                              << point.maxOverlap;
  }
}

double largestError(const std::string& name, const std::string& backend) {
  double largest = 0.0;
  for (const SweepPoint& point : sweep(name, backend))
    largest = std::max(largest, point.error);
  return largest;
}

// Tunnelling. A time-stepped solver sees a contact only where a solver step ends. The shooter
// starts 2.37 r from its twin's centre and closes p·r per step (p = v·h/r): a step must end
// with the centres less than 2r apart and not yet past each other, a window 2r long, or the
// push-out goes the wrong way. So p < 2 always bounces, p > 4 (the whole overlap zone, 4r)
// never can, and between them it depends on the phase: the boundary lies in (2, 4].
void expectTunnelsBetweenTwoAndFourRadii(const std::string& backend, const std::string& variant) {
  for (const SweepPoint& point : curve("tunnelling", backend, variant)) {
    if (point.parameter < 1.99) {
      EXPECT_TRUE(point.passed) << backend << " at " << point.parameter;
    }
    if (point.parameter > 4.01) {
      EXPECT_FALSE(point.passed) << backend << " at " << point.parameter;
    }
  }
  const Boundary boundary = boundaryOf("tunnelling", backend, variant);
  ASSERT_TRUE(boundary.firstFail);
  EXPECT_GT(*boundary.firstFail, 2.0 - 1e-9);
  EXPECT_LE(*boundary.firstFail, 4.0 + 1e-9);
}

TEST(TunnellingBoundary, ElasticTunnelsAtTwoToFourRadiiPerSubstepWhateverTheSize) {
  expectTunnelsBetweenTwoAndFourRadii("elastic", "ball r=0.05 m");
  expectTunnelsBetweenTwoAndFourRadii("elastic", "ball r=0.5 m");
}

TEST(TunnellingBoundary, Box2dTunnelsSmallBallsAtTwoToFourRadiiPerStep) {
  // auto_substeps shortens a Box2D step so no ball moves more than a quarter of
  // b2_maxTranslation (0.5 m) in it: that is 10 r here, still past 4 r, so it keeps tunnelling.
  expectTunnelsBetweenTwoAndFourRadii("box2d", "ball r=0.05 m");
}

TEST(TunnellingBoundary, Box2dNeverTunnelsBallsWiderThanItsPlannedStepTravel) {
  // r = 0.5 m: p ≥ 2 asks for v·h ≥ 1 m, but auto_substeps holds every Box2D step's travel to
  // 0.5 m < 2r, inside the window. So the translation cap's cure also cures tunnelling here.
  for (const SweepPoint& point : curve("tunnelling", "box2d", "ball r=0.5 m"))
    EXPECT_TRUE(point.passed) << "at " << point.parameter << ": error " << point.error;
}

TEST(TunnellingBoundary, NoBackendTunnelsThroughAWall) {
  // Walls are half-planes in elastic and exact (a step ending past one is still seen) and
  // continuous-collision bodies in Box2D.
  for (const std::string backend : {"elastic", "box2d", "exact"}) {
    for (const SweepPoint& point : curve("tunnelling", backend, "wall r=0.05 m"))
      EXPECT_TRUE(point.passed) << backend << " at " << point.parameter;
  }
}

TEST(TunnellingBoundary, ExactNeverTunnels) {
  // Event-driven: the hit happens at its exact time whatever the step.
  EXPECT_LT(largestError("tunnelling", "exact"), kDoubleRounding);
}

// Mass ratio. One two-body contact has a closed-form impulse: elastic and exact apply it in
// double; Box2D's sequential impulses converge on a single contact in the first iteration, in
// float (relative rounding 6e-8).
TEST(MassRatioBoundary, EveryBackendHoldsUpToAMillionToOne) {
  EXPECT_LT(largestError("mass-ratio", "elastic"), kDoubleRounding);
  EXPECT_LT(largestError("mass-ratio", "exact"), kDoubleRounding);
  // Float rounding of O(1) velocities, with room for a few operations: 1e-6, well inside 1e-3.
  EXPECT_LT(largestError("mass-ratio", "box2d"), 1e-6);
}

// Cradle. Hard spheres hit one pair at a time, so the whole momentum must reach the last ball.
TEST(CradleBoundary, ElasticAndExactPassOnDownToTouching) {
  // elastic: touching balls are not overlapping (d = r1 + r2 exactly), so each pair is met in
  // its own substep, one after the other, as the exact solver does by construction.
  EXPECT_LT(largestError("cradle", "elastic"), kDoubleRounding);
  EXPECT_LT(largestError("cradle", "exact"), kDoubleRounding);
}

TEST(CradleBoundary, Box2dFailsOnlyWhenTheBallsTouch) {
  // Box2D makes a contact for touching circles (distance ≤ r1 + r2): the four contacts of a
  // touching row sit in one island and its velocity iterations share the momentum out. With any
  // gap the next ball is met a substep later, alone. The smallest gap tried is 1e-4 r.
  const double touchingDrawnAt = 1e-5;
  for (const SweepPoint& point : sweep("cradle", "box2d")) {
    if (point.parameter > touchingDrawnAt) {
      EXPECT_TRUE(point.passed) << "gap " << point.parameter << " r: error " << point.error;
    } else {
      // Sharing, not rounding: more than half of v0 goes astray.
      EXPECT_GT(point.error, 0.5) << "touching";
    }
  }
}

// Dense packing, at 1 m/s on a triangular lattice. No closed form says where a solver's
// overlaps pass 0.1 r; these brackets pin the quick grid's cells (fractions 0.277, 0.462,
// 0.646, 0.776, 0.822) the current code lands in.
TEST(PackingBoundary, ExactPassesAtEveryFraction) {
  expectPassesEverywhere("packing", "exact");
  EXPECT_LT(largestError("packing", "exact"), kDoubleRounding);
}

TEST(PackingBoundary, ElasticConservesEnergyButOverlapsSmallBallsNearJamming) {
  // Its collision rule conserves energy exactly (a failure can only be an overlap).
  EXPECT_LT(largestError("packing", "elastic"), kDoubleRounding);
  const Boundary small = boundaryOf("packing", "elastic", "64 balls r=0.1 m");
  ASSERT_TRUE(small.lastPass && small.firstFail);
  EXPECT_NEAR(*small.lastPass, 0.646, 0.01);
  EXPECT_NEAR(*small.firstFail, 0.776, 0.01);
  EXPECT_FALSE(boundaryOf("packing", "elastic", "64 balls r=0.2 m").firstFail);
}

TEST(PackingBoundary, Box2dFailsSoonerForSmallerBalls) {
  // Box2D leaves up to its linear slop (0.005 m) of every contact uncorrected: 5% of r = 0.1 m,
  // 2.5% of r = 0.2 m, so the smaller balls reach 0.1 r at a lower packing. The brackets are the
  // measured cells widened by one grid point where the run sits close to a limit (the r = 0.2 m
  // energy error at 0.776 is within 2% of 1e-3).
  const Boundary small = boundaryOf("packing", "box2d", "64 balls r=0.1 m");
  const Boundary large = boundaryOf("packing", "box2d", "64 balls r=0.2 m");
  ASSERT_TRUE(small.firstFail && large.firstFail);
  EXPECT_NEAR(*small.firstFail, 0.462, 0.01);
  EXPECT_GE(*large.firstFail, 0.646 - 0.01);
  EXPECT_LE(*large.firstFail, 0.822 + 0.01);
  EXPECT_LT(*small.firstFail, *large.firstFail);
}

// Scale, 1e-4 to 1e4. elastic and exact work in double with no absolute lengths: the same
// motion at every scale. Box2D's float positions still hold 7 digits of a box 1.6e5 m wide
// (ulp 0.016 m against r = 3000 m), and auto_substeps keeps it under b2_maxTranslation.
TEST(ScaleBoundary, NoBackendFailsFromATenthOfAMillimetreToTenKilometres) {
  for (const std::string backend : {"elastic", "box2d", "exact"})
    expectPassesEverywhere("scale", backend);
  EXPECT_LT(largestError("scale", "elastic"), kDoubleRounding);
  EXPECT_LT(largestError("scale", "exact"), kDoubleRounding);
  // Float rounding over ~100 collisions and a few hundred Box2D steps.
  EXPECT_LT(largestError("scale", "box2d"), 1e-6);
}

// Resting pile, g = 1, 10, 100, 1000 m/s². Where each method gives way is measured, not
// derived: these pin the quick grid's cells.
void expectPileBoundary(const std::string& backend, double lastPass, double firstFail) {
  const Boundary boundary = boundaryOf("pile", backend, "22 balls");
  ASSERT_TRUE(boundary.lastPass && boundary.firstFail) << backend;
  // The grid's values are powers of ten up to the rounding of exp(log(…)).
  EXPECT_NEAR(*boundary.lastPass, lastPass, 1e-9 * lastPass) << backend;
  EXPECT_NEAR(*boundary.firstFail, firstFail, 1e-9 * firstFail) << backend;
}

TEST(PileBoundary, ElasticHoldsUpToTenMetresPerSecondSquared) {
  expectPileBoundary("elastic", 10.0, 100.0);
}

TEST(PileBoundary, Box2dHoldsOnlyUnderEarthlikeGravityOrLess) {
  expectPileBoundary("box2d", 1.0, 10.0);
}

TEST(PileBoundary, ExactGivesWayUnderStrongGravity) {
  // A finding: the pile is a Zeno sequence for an event-driven solver (ever shorter bounces
  // between resting balls), so the solver cuts steps short at its event cap and advances the
  // rest of the step without collisions; under g = 100 m/s² that leaves overlaps past 0.1 r.
  expectPileBoundary("exact", 10.0, 100.0);
}

}  // namespace
