// The test suites' knowledge of each backend: one row per registered backend, each value with
// the reason for it. A bound that must change changes here, in the commit that says why.

#include "backend_profiles.h"

#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include "fooball/run_spec.h"

// The rows name only the fields they set (designated initializers; the rest keep their in-class
// defaults). GCC 12 still warns about the fields left out, which is the point here.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace fooball::testing {
namespace {

/// Double rounding over a few hundred operations on O(1) values; the exact collision rules
/// (closed-form impulses, exact event times) leave nothing else.
constexpr double kDoubleRounding = 1e-12;

constexpr double kBox2dLinearSlop = 0.005;  ///< m, b2_linearSlop (b2_common.h)

// How the rows turn a measurement into a bound. "Measured" means by the test's own check on
// today's code, on the run the test makes (the values are in each row).

/// A closed-form check (conformance, consistency) that a method misses by more than rounding:
/// ten times what it measures, so that a change of method shows and rounding does not.
constexpr double kClosedFormMargin = 10.0;

/// The long gas of tests/consistency/gas_statistics_test.cpp: a sequential-impulse method's drift
/// comes in jumps, a few per run, so three times what one run measures.
constexpr double kGasDriftMargin = 3.0;

/// The default random cases (tests/robustness, seeds 1–2'000) replay bit for bit in every run:
/// twice the worst of them, which lets a small change of a method through and stops a new
/// behaviour. A soak (FOOBALL_SOAK) draws other cases, and one beyond these bounds is a finding.
constexpr double kRandomCaseMargin = 2.0;

/// The worst loss and gain (relative, ≤ 0 and ≥ 0) the default random cases measure, widened by
/// kRandomCaseMargin. A loss beyond −1 is no bound in a closed box (the energy above its lowest
/// point cannot go below 0); the rows say where that is so.
constexpr Interval randomCaseRange(double worstLoss, double worstGain) {
  return {kRandomCaseMargin * worstLoss, kRandomCaseMargin * worstGain};
}

/// A method's real energy gain or loss in a fixed run, pinned both ways within 20% of what it
/// measures: the run is deterministic, so a change of the method in either direction shows.
constexpr Interval pinnedChange(double measured) {
  return around(measured, 0.2 * (measured < 0.0 ? -measured : measured));
}

/// Balls and walls in double precision: positions of boxes up to 200 m round by 1e-14 m, 1e-11
/// of the smallest radius a random case draws (2.5 mm); so 1e-9 of a radius is rounding.
constexpr double kDoubleOverlapRounding = 1e-9;

// Tunnelling. A time-stepped solver sees a contact only where a solver step ends. The shooter
// starts 2.37 r from its twin's centre and closes p·r per step (p = v·h/r): a step must end
// with the centres less than 2r apart and not yet past each other, a window 2r long, or the
// push-out goes the wrong way. So p < 2 always bounces, p > 4 (the whole overlap zone, 4r)
// never can, and between them it depends on the phase: the boundary lies in (2, 4].
constexpr BoundaryExpectation tunnelsBetweenTwoAndFourRadii(std::string_view variant) {
  return {.sweep = "tunnelling",
          .variant = variant,
          .passesBelow = 1.99,
          .failsAbove = 4.01,
          .firstFail = Interval{2.0 - 1e-9, 4.0 + 1e-9}};
}

// Resting pile, g = 1, 10, 100, 1000 m/s². Where each method gives way is measured, not
// derived: these pin the quick grid's cells. The grid's values are powers of ten up to the
// rounding of exp(log(…)).
constexpr BoundaryExpectation pileGivesWayBetween(double lastPass, double firstFail) {
  return {.sweep = "pile",
          .variant = "22 balls",
          .lastPass = around(lastPass, 1e-9 * lastPass),
          .firstFail = around(firstFail, 1e-9 * firstFail)};
}

constexpr BoundaryExpectation kElasticBoundaries[] = {
    // It tunnels at two to four radii per substep, whatever the size.
    tunnelsBetweenTwoAndFourRadii("ball r=0.05 m"),
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // Walls are half-planes (a step ending past one is still seen): it never tunnels a wall.
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    // One two-body contact has a closed-form impulse, applied in double: it holds up to a
    // million to one.
    {.sweep = "mass-ratio", .maxError = kDoubleRounding},
    // Touching balls are not overlapping (d = r1 + r2 exactly), so each pair is met in its own
    // substep, one after the other, as the exact solver does by construction: it passes on down
    // to touching.
    {.sweep = "cradle", .maxError = kDoubleRounding},
    // Dense packing, at 1 m/s on a triangular lattice. Its collision rule conserves energy
    // exactly (a failure can only be an overlap); it overlaps small balls near jamming. No closed
    // form says where a solver's overlaps pass 0.1 r: the bracket pins the quick grid's cells
    // (fractions 0.277, 0.462, 0.646, 0.776, 0.822) the current code lands in.
    {.sweep = "packing", .maxError = kDoubleRounding},
    {.sweep = "packing",
     .variant = "64 balls r=0.1 m",
     .lastPass = around(0.776, 0.01),
     .firstFail = around(0.822, 0.01)},
    {.sweep = "packing", .variant = "64 balls r=0.2 m", .passesEverywhere = true},
    // Scale, 1e-4 to 1e4: double with no absolute lengths, the same motion at every scale.
    {.sweep = "scale", .maxError = kDoubleRounding, .passesEverywhere = true},
    // The pile holds up to ten metres per second squared.
    pileGivesWayBetween(10.0, 100.0),
};

constexpr BoundaryExpectation kBox2dBoundaries[] = {
    // auto_substeps shortens a Box2D step so no ball moves more than a quarter of
    // b2_maxTranslation (0.5 m) in it: that is 10 r here, still past 4 r, so it keeps tunnelling
    // small balls at two to four radii per step.
    tunnelsBetweenTwoAndFourRadii("ball r=0.05 m"),
    // r = 0.5 m: p ≥ 2 asks for v·h ≥ 1 m, but auto_substeps holds every Box2D step's travel to
    // 0.5 m < 2r, inside the window. So the translation cap's cure also cures tunnelling here:
    // it never tunnels balls wider than its planned step travel.
    {.sweep = "tunnelling", .variant = "ball r=0.5 m", .passesEverywhere = true},
    // Walls are continuous-collision bodies: it never tunnels a wall.
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    // Box2D's sequential impulses converge on a single contact in the first iteration, in float
    // (relative rounding 6e-8). Float rounding of O(1) velocities, with room for a few
    // operations: 1e-6, well inside 1e-3. It holds up to a million to one.
    {.sweep = "mass-ratio", .maxError = 1e-6},
    // Box2D makes a contact for touching circles (distance ≤ r1 + r2): the four contacts of a
    // touching row sit in one island and its velocity iterations share the momentum out. With
    // any gap the next ball is met a substep later, alone. The smallest gap tried is 1e-4 r;
    // touching is drawn at 1e-5. It fails only when the balls touch, and there by sharing, not
    // rounding: more than half of v0 goes astray.
    {.sweep = "cradle", .passesAbove = 1e-5, .errorFloor = ErrorFloor{1e-5, 0.5}},
    // Dense packing: Box2D leaves up to its linear slop (0.005 m) of every contact uncorrected:
    // 5% of r = 0.1 m, 2.5% of r = 0.2 m, so the smaller balls reach 0.1 r at a lower packing
    // (the two brackets do not meet, so the small balls fail sooner). The brackets are the
    // measured cells of the quick grid (fractions 0.277, 0.462, 0.646, 0.776, 0.822) widened by
    // one grid point where the run sits close to a limit (the r = 0.2 m energy error at 0.776 is
    // within 2% of 1e-3).
    {.sweep = "packing", .variant = "64 balls r=0.1 m", .firstFail = around(0.462, 0.01)},
    {.sweep = "packing",
     .variant = "64 balls r=0.2 m",
     .firstFail = Interval{0.646 - 0.01, 0.822 + 0.01}},
    // Scale, 1e-4 to 1e4: Box2D's float positions still hold 7 digits of a box 1.6e5 m wide (ulp
    // 0.016 m against r = 3000 m), and auto_substeps keeps it under b2_maxTranslation. The
    // error is float rounding over ~100 collisions and a few hundred Box2D steps.
    {.sweep = "scale", .maxError = 1e-6, .passesEverywhere = true},
    // The pile holds only under earthlike gravity or less.
    pileGivesWayBetween(1.0, 10.0),
};

constexpr BoundaryExpectation kExactBoundaries[] = {
    // Event-driven: the hit happens at its exact time whatever the step; it never tunnels.
    {.sweep = "tunnelling", .maxError = kDoubleRounding},
    // Walls are half-planes: it never tunnels a wall.
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    // One two-body contact has a closed-form impulse, applied in double.
    {.sweep = "mass-ratio", .maxError = kDoubleRounding},
    // Hard spheres hit one pair at a time by construction, so the whole momentum reaches the
    // last ball, down to touching.
    {.sweep = "cradle", .maxError = kDoubleRounding},
    // Dense packing: it passes at every fraction.
    {.sweep = "packing", .maxError = kDoubleRounding, .passesEverywhere = true},
    // Scale, 1e-4 to 1e4: double with no absolute lengths, the same motion at every scale.
    {.sweep = "scale", .maxError = kDoubleRounding, .passesEverywhere = true},
    // The pile is a Zeno sequence for an event-driven solver (ever shorter bounces between
    // resting balls); the ball rest rule (ball_rest_time, default 0.01 s) lays it to sleep in its
    // first events at every gravity, run without the map's event cap. Measured (quick grid, 1 to
    // 1000 m/s²): energy error 1e-17 to 2e-16, overlap 5.6e-16 of a radius: rounding.
    {.sweep = "pile", .maxError = kDoubleRounding, .passesEverywhere = true},
};

constexpr BoundaryExpectation kXpbdBoundaries[] = {
    // It finds ball contacts on the predicted centres at the end of each substep and pushes the
    // pair apart along the line of centres: the same window as elastic's, two to four radii per
    // substep, whatever the size.
    tunnelsBetweenTwoAndFourRadii("ball r=0.05 m"),
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // Walls are half-planes (a centre predicted past one is put back): it never tunnels a wall.
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    // One contact alone: the projection moves each ball by its inverse-mass share and the
    // velocity pass reverses the pre-solve normal velocity with the same shares, the closed-form
    // elastic result in double. It holds up to a million to one.
    {.sweep = "mass-ratio", .maxError = kDoubleRounding},
    // With any gap (down to 1e-4 r) the next ball is met a substep later, alone, and takes the
    // whole momentum. A touching row is in contact at once (the centres of a touching row lie
    // 2r apart to rounding, so some pairs overlap by an ulp): the first projection pushes the
    // whole row and the velocity pass gives every contact that was not approaching a normal
    // velocity of 0, which shares the momentum out, as Box2D's island does: more than half of
    // v0 goes astray (measured 2.1).
    {.sweep = "cradle", .passesAbove = 1e-5, .errorFloor = ErrorFloor{1e-5, 0.5}},
    // Dense packing, at 1 m/s on a triangular lattice. Overlaps stay small (under 2% of r), but
    // the energy moves by more than 1e-3 once several contacts share a ball in one substep
    // (Gauss–Seidel over simultaneous contacts, whose restitution targets are not met together
    // in 4 iterations), which happens at lower packing for the smaller balls (their gaps are
    // smaller at the same fraction). No closed form says where: the brackets pin the quick
    // grid's cells (fractions 0.277, 0.462, 0.646, 0.776, 0.822) the current code lands in
    // (measured errors: r = 0.1 m 3.4e-3 at 0.462; r = 0.2 m 6.1e-5 at 0.462, 1.9e-3 at 0.646).
    {.sweep = "packing",
     .variant = "64 balls r=0.1 m",
     .lastPass = around(0.277, 0.01),
     .firstFail = around(0.462, 0.01)},
    {.sweep = "packing",
     .variant = "64 balls r=0.2 m",
     .lastPass = around(0.462, 0.01),
     .firstFail = around(0.646, 0.01)},
    // Scale, 1e-4 to 1e4: double with no absolute lengths (the substep, the projection and the
    // velocity pass scale with the scene), the same motion at every scale. In this sparse gas
    // every contact is alone in its substep, and a lone contact keeps the energy to rounding
    // (measured 1e-14 to 8e-14).
    {.sweep = "scale", .maxError = kDoubleRounding, .passesEverywhere = true},
    // The pile: each ball falls g·h² into the one below per substep and is pushed out, and the
    // velocity pass turns the g·h of approach around, so a pile under gravity jiggles. The
    // energy error grows with g (measured, in Σ m·g·r: 1.3e-4 at g = 1, 3.0e-3 at 10, 0.028 at
    // 100, 0.27 at 1000 m/s²): it holds up to a hundred metres per second squared.
    pileGivesWayBetween(100.0, 1000.0),
};

constexpr BoundaryExpectation kChipmunkBoundaries[] = {
    // No continuous collision between balls: like the elastic solver it tunnels at two to four
    // radii per substep, at any size (Chipmunk has no translation cap to shorten its steps).
    // Measured: both curves pass up to 2 and fail from 2.38 (the next grid point).
    tunnelsBetweenTwoAndFourRadii("ball r=0.05 m"),
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // Walls: a ball that crosses one within a step is caught by the wall's thickness or brought
    // back by the adapter's containment (backends/chipmunk/wall_containment.h): it never tunnels
    // a wall.
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    // One two-body contact: Chipmunk's first impulse iteration reaches the elastic target exactly
    // (the effective mass 1/(1/m1 + 1/m2) in double), and the later ones add nothing. Measured
    // ≤ 2.2e-16 up to a million to one.
    {.sweep = "mass-ratio", .maxError = kDoubleRounding},
    // Chipmunk makes a contact only for strictly overlapping circles, and a touching row
    // (1e-5 r, the closest the sweep draws) is not overlapping: each pair is met in its own
    // substep, one after the other, so the whole momentum reaches the last ball (measured
    // ≤ 4.7e-18), down to touching — unlike Box2D, whose contacts begin at touching.
    {.sweep = "cradle", .maxError = kDoubleRounding},
    // Dense packing at 1 m/s: no closed form says where a solver's overlaps pass 0.1 r; the
    // brackets pin the quick grid's cells (fractions 0.277, 0.462, 0.646, 0.776, 0.822) the
    // current code lands in. r = 0.1 m fails from 0.462 on overlap (0.134 r: a substep's travel
    // at the gas's fastest speeds, beside a neighbour); r = 0.2 m from 0.776 on energy (3.7e-3:
    // jammed balls whose several contacts Chipmunk's iterations solve one after the other).
    {.sweep = "packing",
     .variant = "64 balls r=0.1 m",
     .lastPass = around(0.277, 0.01),
     .firstFail = around(0.462, 0.01)},
    {.sweep = "packing",
     .variant = "64 balls r=0.2 m",
     .lastPass = around(0.646, 0.01),
     .firstFail = around(0.776, 0.01)},
    // Scale, 1e-4 to 1e4: double state, and the slop is a fraction of the radius (not
    // Chipmunk's absolute 0.1), so the same motion at every scale. Measured ≤ 6e-16.
    {.sweep = "scale", .maxError = kDoubleRounding, .passesEverywhere = true},
    // The pile holds up to ten metres per second squared (the position bias removes each step's
    // overlap in the next: backends/chipmunk/contact_slop.h; energy error 7.6e-3 of Σ m·g·r at
    // g = 10, 0.12 at g = 100, overlap 0.35 r).
    pileGivesWayBetween(10.0, 100.0),
};

// Bullet at its defaults (one Bullet step per frame, its solver's own settings). It finds contacts
// where a step starts, so a contact is up to a step's travel deep when it is seen, and its
// split-impulse threshold turns overlaps shallower than 4 cm into speed, deeper ones not
// (backends/bullet/split_impulse.h): it fails wherever a first overlap is shallower than 4 cm.
constexpr BoundaryExpectation kBulletBoundaries[] = {
    // The 0.05 m ball overlaps by v·h: below 4 cm (v·h/r ≤ 0.8, measured up to 1) the push gives
    // an error of 0.052–0.126; from 1.19 to 2 the overlap is split and the hit exact (3e-8: float);
    // beyond 2 r a step it tunnels, as the time-stepped methods do (measured from 2.38).
    {.sweep = "tunnelling",
     .variant = "ball r=0.05 m",
     .failsAbove = 2.01,
     .errorFloor = ErrorFloor{1.0, 0.05},
     .firstFail = around(0.5, 1e-9)},
    // The 0.5 m ball overlaps by at least 0.25 m, always split: it passes until it tunnels.
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // A wall plane is a half-space (backends/bullet/wall_planes.h): never tunnelled; the
    // 0.05 m ball fails against it as against a ball where its overlap is shallow.
    {.sweep = "tunnelling",
     .variant = "wall r=0.05 m",
     .maxError = 0.2,
     .passesAbove = 1.1,
     .errorFloor = ErrorFloor{1.0, 0.05}},
    // One head-on hit: the first step's overlap becomes speed, 0.10–0.20 of v0 (measured), at every
    // mass ratio.
    {.sweep = "mass-ratio",
     .maxError = 0.25,
     .failsAbove = 0.99,
     .errorFloor = ErrorFloor{1e6, 0.09}},
    // The cradle's momentum goes astray at every gap: 0.16 of v0 at a gap of r to 0.78 touching.
    {.sweep = "cradle", .failsAbove = 0.0, .errorFloor = ErrorFloor{1.0, 0.15}},
    // Dense packing: the energy grows by 0.49 (r = 0.2 m, the least packed) to 1e5 times.
    {.sweep = "packing", .failsAbove = 0.0, .errorFloor = ErrorFloor{0.84, 0.4}},
    // Scale: 5.1% energy error at every scale up to 1e3 (measured 0.0509–0.051); at 1e4 the
    // energy holds but the overlaps do not.
    {.sweep = "scale", .failsAbove = 0.0, .errorFloor = ErrorFloor{1e3, 0.04}},
    // The pile: 3.1 (g = 1) to 125 (g = 1000) times Σ m·g·r.
    {.sweep = "pile", .failsAbove = 0.0, .errorFloor = ErrorFloor{1000.0, 2.5}},
};

// matter.js at its users' settings (resting threshold 2 px per frame, 1.9 m/s at 64 px/m): the
// map's scenes move at 1–3 m/s, so most of its failures are that threshold's inelastic "resting"
// contacts, measured on the quick grid (full grid for tunnelling).
constexpr BoundaryExpectation kMatterBoundaries[] = {
    // Between balls it bounces from 0.71 to 2 radii per step and passes through from 2.83 on (no
    // continuous collision); at 0.5 the shot is slower than the resting threshold and stops.
    {.sweep = "tunnelling", .variant = "ball r=0.05 m", .failsAbove = 2.01},
    // Its 1 m thick walls hold every speed tried from 0.71 radii per step on (error ≤ 1.9e-15).
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesAbove = 0.6},
    // The map's head-on hit is slower than the resting threshold at every mass ratio: the balls
    // meet as a resting contact and move off together (error 1 at 1:1, towards 2 beyond).
    {.sweep = "mass-ratio", .failsAbove = 0.5},
    // The cradle's shot is fast enough: measured ≤ 3.0e-14 at every gap, down to touching.
    {.sweep = "cradle", .maxError = kDoubleRounding, .passesEverywhere = true},
    // Dense packing at 1 m/s: every hit is below the threshold; it loses 38–99% of the energy.
    {.sweep = "packing", .failsAbove = 0.2},
    // Scale: speeds of 1–3·s m/s against a threshold fixed in pixels per frame: it fails from
    // 1e-3 to 1 (energy −0.9% to −43%) and holds from 10 on (measured ≤ 1.8e-14).
    {.sweep = "scale", .passesAbove = 5.0},
    // The pile loses energy (0.099 of Σ m·g·r at g = 1, 2.8 at 1000) and sinks deeper than 0.1 r
    // at every g tried.
    {.sweep = "pile", .failsAbove = 0.5},
};

// Box2D v3 at its users' settings, measured on the quick grid (full grid for tunnelling).
constexpr BoundaryExpectation kBox2d3Boundaries[] = {
    // Its speculative contacts met every shot of the small ball, at a ball and at a wall, up to 16
    // radii per step (one Box2D step: it finds contacts once a step, the sub-steps only solve
    // them); the 0.5 m ball passes through its twin as the time-stepped methods do, from 2.38
    // radii per step.
    {.sweep = "tunnelling", .variant = "ball r=0.05 m", .passesEverywhere = true},
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // One contact solved in float: ≤ 2.7e-7 up to a million to one.
    {.sweep = "mass-ratio", .maxError = 1e-6, .passesEverywhere = true},
    // The cradle holds with gaps of 0.1 r and more (3.6e-7); from 0.01 r its soft contacts share
    // the momentum out along the row (error 1.3–1.6).
    {.sweep = "cradle",
     .variant = "gaps",
     .lastPass = around(0.1, 1e-9),
     .firstFail = around(0.01, 1e-9)},
    // Dense packing at 1 m/s fails from the lowest tried: it loses 7.1% of the energy and lets
    // balls in 0.18 r at 0.277 for r = 0.1 m, overlaps 0.069 r and loses 0.27% for 0.2 m.
    {.sweep = "packing", .failsAbove = 0.2},
    // Scale: it holds from 1e-4 to 1 (energy ≤ 9e-8, overlap 0.065 r at 1) and fails from 10 on
    // (overlap 0.17 r at 10: its push-out speed, 3 m/s, is absolute; energy −97% at 1'000).
    {.sweep = "scale", .passesBelow = 5.0, .failsAbove = 5.0},
    // The pile holds to ten metres per second squared (energy 0.013 of Σ m·g·r), not 100 (0.13).
    pileGivesWayBetween(10.0, 100.0),
};

// Rapier 2D 0.21.0 at its users' settings, measured on the quick grid (full grid for tunnelling).
constexpr BoundaryExpectation kRapierBoundaries[] = {
    // Its contacts are predictive (a prediction distance ahead of the surface, an absolute
    // length): it met every shot of the small ball, at a ball and at a wall, up to 16 radii per
    // step (error ≤ 8e-8, float); the 0.5 m ball, whose radii the prediction covers less of,
    // tunnels as the time-stepped methods do, from 2.38 radii per step.
    {.sweep = "tunnelling", .variant = "ball r=0.05 m", .passesEverywhere = true},
    {.sweep = "tunnelling", .variant = "wall r=0.05 m", .passesEverywhere = true},
    tunnelsBetweenTwoAndFourRadii("ball r=0.5 m"),
    // One contact solved in float: ≤ 1.9e-7 up to a million to one.
    {.sweep = "mass-ratio", .maxError = 1e-6, .passesEverywhere = true},
    // The cradle holds with gaps of 0.1 r and more; from 0.01 r its soft contacts share the
    // momentum out along the row (error 1.1–1.6).
    {.sweep = "cradle",
     .variant = "gaps",
     .lastPass = around(0.1, 1e-9),
     .firstFail = around(0.01, 1e-9)},
    // Dense packing at 1 m/s: its soft contacts lose energy (2.2% at 0.277 for r = 0.1 m, 0.9%
    // for 0.2 m, up to all of it near jamming) and let balls sink 0.22 r: fails from the lowest.
    {.sweep = "packing", .failsAbove = 0.2},
    // Scale: it holds at 0.1 and 1 and fails below (−4.1%: its allowed linear error and prediction
    // distance are absolute lengths) and above (overlap 0.17 r at 10, energy at 100 and beyond).
    {.sweep = "scale", .failsAbove = 5.0},
    // The pile holds to ten metres per second squared (energy 0.011 of Σ m·g·r), not 100.
    pileGivesWayBetween(10.0, 100.0),
};

constexpr std::array<BackendProfile, 9> kProfiles = {{
    {
        .name = "elastic",
        // Double precision with exact collision rules: the derived double-rounding defaults
        // (measured: momentum 4.2e-17, energy 6.7e-16, under gravity −1.7e-15), and velocity and
        // position 10× what they measure (1.1e-15 m/s of the 1 m/s that setWorld's gravity gives in
        // 0.5 s; 3.4e-13 m after 2 s of flight through a wall that is off).
        .conformance = {.velocity = kClosedFormMargin * 1.1e-15,
                        .position = kClosedFormMargin * 3.4e-13},
        // Its resting pile takes up a little energy (0.08 → 0.20 J of kinetic energy over 3 s,
        // the resting-pile limit of docs/accuracy.md): floor balls hop past the release distance
        // 2.5 times a second (of 80). Twice that.
        .wallCount = {.restingPilePerSecond = 2.0 * 2.5},
        .methodError =
            {
                .timeStepped = true,
                // It moves the overlapping balls back to touching and reverses u there, so they
                // are u·τ short of the exact separation u·τ (factor 1).
                .contactLag = 1.0,
                // It reflects the ball at the exact time it crossed the wall, under gravity too
                // (factor 0).
                .wallLag = 0.0,
                // Exact flight (closed-form parabola and exponential); double rounding is held
                // by the 1e-9 floor.
                .eulerFlight = false,
            },
        // It conserves energy per collision to double rounding: ~3e4 collisions and bounces in the
        // run, each rounding the energy by a few ε (4 × 1.1e-16), 1.3e-11 at most; 3e-11.
        // Measured: 4.4e-16 at the end, 1.1e-15 on average.
        .gasEnergyDrift = 3e-11,
        // Double precision, exact flight, and impulses and wall reflections that keep the energy to
        // rounding: in every world both ways to ten times the worst of the default cases, 1.4e-11
        // (seed 744: 16 balls falling out of an open box under gravity). Overlaps after resolved
        // steps: it separates every overlapping pair to contact, so on its own it leaves none
        // beyond rounding (measured 1.2e-14 of the smaller radius); one pair after another, so
        // where tools press a crowd together it can leave some (twice the worst, kRandomCaseMargin:
        // 0.128, seed 825: 70 balls under a slingshot); walls reflect exactly (measured 0).
        .robustness = {.energyWithoutGravity = eitherWay(kClosedFormMargin * 1.41e-11),
                       .energyUnderGravity = eitherWay(kClosedFormMargin * 1.41e-11),
                       .energyUnderGravityWithCollisions = eitherWay(kClosedFormMargin * 1.41e-11),
                       .energyUnderGravityOpen = eitherWay(kClosedFormMargin * 1.41e-11),
                       .energyAbsolute = 1e-12,
                       .wallSlack = 0.0,
                       .ballOverlap = kDoubleOverlapRounding,
                       .ballOverlapWithInteractions = kRandomCaseMargin * 0.128,
                       .wallOverlap = kDoubleOverlapRounding},
        // None: its cost is fixed by the case (balls, steps, substeps, threads), which drawCase
        // bounds.
        .workCap = {},
        // FINDING (reported to the coordinator): with ball collisions on, under gravity the elastic
        // solver can gain energy, in none of the default 2'000 cases but in 12 of seeds
        // 2'001–20'000 (FOOBALL_SOAK=20000): the most 9.8e-4 in seed 15422 (96 balls in a closed
        // 63.8 × 15.8 m box under g = 526 m/s², 36 steps of 17.5 ms, one substep; earlier 1.8% in
        // a longer run of 22 balls at g = 825 m/s²). A ball that a neighbour pushes into a wall is
        // put back at contact, which lifts it against gravity; the lift is paid from its inward
        // speed, but a ball resting in a pile has too little. With the pair search always from
        // the lower left (before CellOrder) it was 7 seeds, the most 6.0e-4 in seed 2324 (now
        // 2.9e-5 there).
        .energyFinding = {.seed = 15422, .relativeChange = pinnedChange(9.846e-4)},
        .determinismHash = 3187512781587505975u,
        .failureMap = kElasticBoundaries,
    },
    {
        .name = "box2d",
        // Box2D stores float (ε = 1.2e-7), and its sequential impulses with restitution 1 resolve
        // contacts only to within their iterations. Momentum, derived from float rounding: each
        // of the ~920 collisions in 3 s of the gas with the walls off rounds the pair's
        // velocities to float (ε/2 each), a pair holding ~1/300 of Σ m|v|: at most
        // 920 × 2 × 6e-8 / 300 = 3.7e-7, so 4e-7 (measured 3.9e-9; one collision alone, in
        // cli_test, 3.3e-8). The rest 10× what each check measures: energy −1.2e-7 over 5 s;
        // velocity 6.0e-7 of the 1 m/s setWorld's gravity gives in 0.5 s (float steps); position
        // 2.1e-4 m after 2 s of flight at 3 m/s through a wall that is off (float positions at
        // 20 m). Under gravity the gas gains energy: +3.5% in 5 s, pinned.
        .conformance = {.momentum = 4e-7,
                        .energy = kClosedFormMargin * 1.2e-7,
                        .energyUnderGravity = pinnedChange(0.0351),
                        .velocity = kClosedFormMargin * 6.0e-7,
                        .position = kClosedFormMargin * 2.1e-4},
        // Restitution 1 with threshold 0 never lets a ball rest (backends/box2d/contact_counter.h):
        // the pile heats up (0 → 2.7 J of kinetic energy in 3 s) and its floor balls hop by more
        // than a tenth of their radius, 260 times a second of 80 balls: real hops, counted (it
        // counted 2'110 a second, every broken contact, before the rule). Twice that.
        .wallCount = {.restingPilePerSecond = 2.0 * 260.5},
        .methodError =
            {
                .timeStepped = true,
                // Its velocity solver reverses u while the overlap u·τ remains, and the next
                // position update only flies it out, so the overlap is never undone and the
                // separation is 2u·τ short (factor 2). Its iterative velocity solver adds nothing
                // here: one contact alone is solved exactly by the first iteration, and the
                // position solver leaves alone an overlap that the step has flown out.
                .contactLag = 2.0,
                // It reverses u at the wall overlap (factor 2).
                .wallLag = 2.0,
                // Box2D's continuous collision against the walls (static bodies) stops a ball at
                // a target depth of 3 linear slops (3 × 5 mm) with a tolerance of a quarter slop
                // (b2_time_of_impact).
                .contactDepthFloor = 3.25 * kBox2dLinearSlop,
                // Box2D integrates gravity and drag with semi-implicit Euler (v += h·g;
                // x += h·v).
                .eulerFlight = true,
                // Box2D stores float: ½ ulp(8 … 16 m) = 2^−21 m.
                .positionRoundingPerStep = 0x1p-21,
                // float ε = 2^−23.
                .velocityRoundingPerStep = std::numeric_limits<float>::epsilon(),
            },
        // Box2D stores float velocities (ε = 1.2e-7 per component per collision: a random walk of
        // ~1e-7 over the run), but its drift comes in rare jumps: sequential impulses with
        // restitution 1 resolve contacts found late, and several at once, one after another, which
        // does not keep the energy of a touching group. Measured +1.4e-3 at the end and +1.48e-3 on
        // average (earlier seeds and wall variants of the adapter: −7e-5 to +4.5e-3); three times
        // the larger, kGasDriftMargin.
        .gasEnergyDrift = kGasDriftMargin * 1.48e-3,
        // Box2D's contacts rest at a penetration of b2_linearSlop (5 mm, b2_common.h), and its
        // continuous collision against the walls stops a fast ball where it overlaps the wall by up
        // to 3.25 slops (b2TimeOfImpact: target separation r − 3·slop, tolerance slop/4): 16.25 mm.
        // A ball smaller than that may end with its centre beyond the wall by the difference. Where
        // the continuous collision gives up (in crowds of bullets), the adapter puts the ball back
        // (backends/box2d/wall_containment.h, the same 3.25 slops). Beyond that slack its float
        // positions round by up to 7.6e-6 m at 200 m, 0.3% of the smallest radius drawn: 0.01
        // (measured 0).
        // Energy, twice the worst of the default cases (kRandomCaseMargin), each world both ways:
        // without gravity it loses up to 0.55% (seed 757, stopped by the work cap: bullets in a
        // crowd) and gains nothing beyond 1e-4 of the energy scale (float rounding near 0 J). Under
        // gravity it gains far beyond float and solver error, a finding (reported to the
        // coordinator): +89% with ball collisions off (seed 417, pinned below), +111% with them on
        // (seed 1764: 165 balls), and loses up to 1.8% and 35% (seeds 1296, 1329). With a wall off,
        // balls fall for good and semi-implicit Euler loses ½·m·|g|²·h per ball and second on top
        // of the translation cap's losses: up to 312 times the energy at the start (seed 1416), no
        // bound worth the name below. Overlaps after resolved steps, the same margin: it resolves
        // contacts over several steps (position iterations, slop): 0.215 of the smaller radius on
        // its own (seed 264: 198 balls of two sizes after one step), 0.187 with interactions (seed
        // 238).
        .robustness = {.energyWithoutGravity = randomCaseRange(-5.46e-3, 0.0),
                       .energyUnderGravity = randomCaseRange(-1.83e-2, 0.893),
                       .energyUnderGravityWithCollisions = randomCaseRange(-0.346, 1.11),
                       .energyUnderGravityOpen = randomCaseRange(-312.0, 3.94e-2),
                       .energyAbsolute = 1e-4,
                       .wallSlack = 3.25 * kBox2dLinearSlop,
                       .ballOverlap = kRandomCaseMargin * 0.215,
                       .ballOverlapWithInteractions = kRandomCaseMargin * 0.187,
                       .wallOverlap = 0.01},
        // Box2D steps × (balls + 1). Under gravity Box2D's energy can grow without bound (the
        // finding above), and auto_substeps then raises its steps towards 1000 a step: such a
        // case took 2 minutes (15 balls, 371 steps, 200'000 Box2D steps). 200'000 is 1000 Box2D
        // steps of 200 balls, ~0.1 s for an ordinary case, but continuous collision of fast
        // bullets in piles costs up to 40 µs a ball and Box2D step: 8 of the default 2'000 cases
        // reach it.
        .workCap = {.counter = "box2d_steps", .perBall = true, .max = 200'000.0},
        // 22 balls in a closed 1.9 × 0.94 m box under g = 64 m/s², ball collisions off, 125 steps
        // of 22 ms, 4 substeps: the wall contacts alone raise the energy by 89%.
        .energyFinding = {.seed = 417, .relativeChange = pinnedChange(0.8934)},
        .determinismHash = 13898907332539593637u,
        .failureMap = kBox2dBoundaries,
        // Continuous collision at up to 1000 auto substeps: the dense preset (759 balls) with
        // ball collisions off and a strong attractor spent over 4 minutes in b2World::SolveTOI
        // on one step (the monkey's seed, action 524, with box2d as a compare run).
        .stepsCanTakeMinutes = true,
    },
    {
        .name = "exact",
        // Exact by construction: the derived double-rounding defaults (measured: momentum 7.3e-17,
        // energy 8.9e-16, under gravity −1.1e-16, velocity 1.1e-16), and position 10× what it
        // measures (8.5e-14 m after 2 s of flight through a wall that is off).
        .conformance = {.position = kClosedFormMargin * 8.5e-14},
        // Event-driven: exact collision times, exact flight.
        // A resting pile is a Zeno sequence for it (the pile sweep's finding below): uncapped, a
        // second of this pile takes minutes. It is counted as the app runs piles, with a cap;
        // measured 82 → 84 collisions in 2 s after the first.
        // The wall rule alone: with the ball resting rule on (its default), this pile begins 42
        // wall collisions a second, and they are real (issue 38, traced with the pile's state
        // each second): the pile does not stay at rest. Its kinetic energy grows from 0 to 0.42 J
        // after 1 s and 0.83 J after 3 s (0.11 → 0.16 J with the rule off), and 2 to 5 balls of
        // the bottom row at a time leave the floor at up to 0.77 m/s, to rise 1.3–3.1 cm, beyond
        // the 1 cm (r/10) after which the wall's next action is a new collision. Counted right;
        // which of the rule's kicks and wakes stirs the pile is not yet traced.
        .wallCount = {.options = "max_events_per_ball=10,ball_rest_time=0",
                      .restingPilePerSecond = 2.0},
        .methodError = {},
        // It conserves energy per collision to double rounding, as elastic: 3e-11. Measured
        // −2.0e-15 at the end, −1.6e-15 on average.
        .gasEnergyDrift = 3e-11,
        // Double precision: exact event times, flight and reflections keep the energy to rounding
        // once the energy it reports laying balls to rest on a wall takes out (rest_energy_change:
        // a bounce that returns within rest_bounce_time, which a random case draws up to 1 s, drops
        // at most m(g t/2)²/2). In every world both ways to ten times the worst of the default
        // cases, 3.4e-11 (seed 744, the open box where elastic measures its worst). No overlap
        // beyond rounding (measured 0 between balls, 2.3e-12 of a radius at walls) at any speed,
        // until a step is cut short at the event cap (max_events_per_ball, drawn as low as 1) and
        // the rest of it advances without collisions (counted in cutShortSteps): 54 of the default
        // cases.
        .robustness = {.energyWithoutGravity = eitherWay(kClosedFormMargin * 3.39e-11),
                       .energyUnderGravity = eitherWay(kClosedFormMargin * 3.39e-11),
                       .energyUnderGravityWithCollisions = eitherWay(kClosedFormMargin * 3.39e-11),
                       .energyUnderGravityOpen = eitherWay(kClosedFormMargin * 3.39e-11),
                       .energyAbsolute = 1e-12,
                       .reportedEnergyChange = "rest_energy_change",
                       .wallSlack = 0.0,
                       .ballOverlap = kDoubleOverlapRounding,
                       .ballOverlapWithInteractions = kDoubleOverlapRounding,
                       .wallOverlap = kDoubleOverlapRounding,
                       .resolvedTravel = std::numeric_limits<double>::infinity()},
        // Events. Piles under strong gravity make event cascades that fill the event cap of
        // every step (cutShortSteps), and a ball resting on a wall next to a flying one takes
        // an iterative contact search (~30 µs an event): such cases took up to 9 s. 30'000 events
        // are 150 per ball for 200 balls, ~10 ms in a gas and under 1 s at worst; 42 of the
        // default 2'000 cases reach it, most of them cascades, each after dozens of cut-short
        // steps.
        .workCap = {.counter = "events", .perBall = false, .max = 30'000.0},
        .energyFinding = {},
        .determinismHash = 256026291394485770u,
        .failureMap = kExactBoundaries,
    },
    {
        .name = "xpbd",
        // Double precision, and a lone contact keeps momentum and energy to rounding (both the
        // projection and the velocity pass move the pair by inverse-mass shares, and the pass
        // reverses the pre-solve normal velocity). Its energy moves where several contacts share a
        // ball in one substep: Gauss–Seidel over simultaneous contacts with restitution targets
        // from before the solve, and contacts that were not approaching lose their normal velocity
        // (min(−v̄_n, 0) = 0). 10× what each check measures: energy +0.40% in this gas (300 balls, 5
        // s, default 8 substeps × 4 iterations); velocity 4.6e-13 (the head-on pair's);
        // position 8.0e-13 m (2 s of flight through a wall that is off); momentum at the derived
        // default (measured 2.5e-14). Under gravity the gas loses energy: −3.2% in 5 s, pinned.
        .conformance = {.energy = kClosedFormMargin * 4.0e-3,
                        .energyUnderGravity = pinnedChange(-0.0324),
                        .velocity = kClosedFormMargin * 4.6e-13,
                        .position = kClosedFormMargin * 8.0e-13},
        .methodError =
            {
                .timeStepped = true,
                // It finds the pair overlapping by u·τ on the predicted centres, projects it
                // back to touching and reverses u there: u·τ short of the exact separation, as
                // elastic (factor 1).
                .contactLag = 1.0,
                // It puts a ball predicted D past a wall back at the wall with its pre-solve
                // speed reversed: D behind (factor 1 without gravity). Under gravity that speed
                // is the speed after the whole substep's fall (h·u) while the ball fell only
                // h·u − D, so it flies out on a parabola with up to |g|·h·u less energy per kg
                // (speed |g|·h = |g|·(u·h)/u lower). The bounce model of the consistency test
                // bounds the speed change by ½|g|·lag/u: lag = 2·D_max (factor 2).
                .wallLag = 2.0,
                // v += h·g; x += h·v: semi-implicit Euler, as Box2D.
                .eulerFlight = true,
            },
        // The thermalised gas (300 balls, 45 s) lost 0.61% of its kinetic energy at the end, 0.32%
        // on average (Gauss–Seidel over simultaneous contacts, see conformance): three times the
        // larger.
        .gasEnergyDrift = kGasDriftMargin * 6.14e-3,
        // Double precision, every ball put back inside the walls that are on at the end of every
        // substep (wall slack 0; measured 5.6e-14 of a radius). Energy, twice the worst of the
        // default cases (kRandomCaseMargin), both ways: it gains at most 1.4e-5 without gravity
        // (seed 1565, one substep: simultaneous contacts), 1.5e-5 under gravity with collisions
        // off, 2.4e-3 with them on (seed 397: 19 balls under g = 19.7 m/s², one substep of 9 ms;
        // semi-implicit Euler reports an energy that swings by m·|g|·h·|v| about its conserved one)
        // and 2.4e-4 in an open box. It loses where contacts crowd: 47% without gravity (seed 1047:
        // 178 balls), and under gravity nearly all the energy a pile holds above the floor (57%,
        // 98%, 98%: seeds 1499, 368, 1562), so there the loss side bounds nothing; conformance pins
        // its loss under gravity both ways. Overlaps after resolved steps, the same margin: 2.0e-4
        // of the smaller radius on its own (seed 645: contacts its 4 iterations leave), 0.115 with
        // interactions (seed 825).
        .robustness = {.energyWithoutGravity = randomCaseRange(-0.474, 1.36e-5),
                       .energyUnderGravity = randomCaseRange(-0.571, 1.45e-5),
                       .energyUnderGravityWithCollisions = randomCaseRange(-0.983, 2.44e-3),
                       .energyUnderGravityOpen = randomCaseRange(-0.98, 2.35e-4),
                       .energyAbsolute = 1e-12,
                       .wallSlack = 0.0,
                       .ballOverlap = kRandomCaseMargin * 2.02e-4,
                       .ballOverlapWithInteractions = kRandomCaseMargin * 0.115,
                       .wallOverlap = kDoubleOverlapRounding},
        // None: its cost is fixed by the case (balls, steps, substeps, iterations), which
        // drawCase bounds.
        .workCap = {},
        .energyFinding = {},
        .determinismHash = 16942831552505709587u,
        .failureMap = kXpbdBoundaries,
    },
    {
        .name = "chipmunk",
        // Chipmunk's cpFloat is double (Debian's build). Momentum at the derived default (measured
        // 9e-17 of Σ m|v|). Its energy is not exact: where one ball's several contacts are solved
        // in one step, its sequential impulses treat them one after the other. 10× what each check
        // measures: energy −9.5e-9 over 5 s; velocity 1.1e-15 (setWorld's gravity);
        // position 3.4e-13 m (flight through a wall that is off). Under gravity the gas loses
        // energy: −1.0% in 5 s, pinned.
        .conformance = {.energy = kClosedFormMargin * 9.5e-9,
                        .energyUnderGravity = pinnedChange(-0.01027),
                        .velocity = kClosedFormMargin * 1.1e-15,
                        .position = kClosedFormMargin * 3.4e-13},
        .methodError =
            {
                .timeStepped = true,
                // It finds the contact at the end of the substep's position update and reverses
                // u there; the overlap u·τ is then flown out (factor 2), less what the position
                // bias pushes apart in the next position update (up to the whole overlap with the
                // default collision_bias 0: factor 1). 2 bounds both.
                .contactLag = 2.0,
                // The same at a wall.
                .wallLag = 2.0,
                // The adapter kicks gravity and drag into the velocities before each Chipmunk
                // step, which then moves the positions: semi-implicit Euler (v += h·g;
                // x += h·v), as Box2D (backends/chipmunk/flight.h).
                .eulerFlight = true,
                // double state: rounding is held by the 1e-9 floor.
            },
        // Measured over this scene: −4.7e-7 at the end, −3.0e-7 on average (a loss: the sequential
        // impulses of simultaneous contacts, see conformance above); three times the larger.
        .gasEnergyDrift = kGasDriftMargin * 4.7e-7,
        // Double state. Walls: the adapter brings back a ball whose centre crosses a wall,
        // mirrored inside (wall_containment.h), so no slack; short of that a ball rests in a wall
        // by the collision_slop its position correction leaves alone, and deeper while
        // collision_bias (drawn up to 1: no correction) leaves the rest: 0.198 of its radius after
        // resolved steps (seed 125: slop 0, bias 0.68, one iteration, under gravity). Energy, twice
        // the worst of the default cases (kRandomCaseMargin), both ways: without gravity it loses
        // up to 0.96% (seed 757: a crowd whose contacts a single sequential-impulse pass leaves
        // unresolved) and gains nothing beyond rounding; under gravity it gains at most 2.8e-6 with
        // ball collisions off, 7.5e-4 with them on (seed 383: 57 balls under g = 1.5 m/s², one
        // substep and one iteration) and 1.4e-5 in an open box, and loses nearly all the energy a
        // settling pile holds above the floor (92% and 100%: seeds 417, 833), so there the loss
        // side bounds nothing; conformance pins its loss under gravity both ways. In an open box
        // balls fall for good under semi-implicit Euler: −10 times the energy at the start (seed
        // 268). Overlaps after resolved steps, the same margin: 0.215 of the smaller radius on its
        // own (seed 264, as Box2D), 0.175 with interactions (seed 238).
        .robustness = {.energyWithoutGravity = randomCaseRange(-9.64e-3, 0.0),
                       .energyUnderGravity = randomCaseRange(-0.918, 2.84e-6),
                       .energyUnderGravityWithCollisions = randomCaseRange(-1.0, 7.45e-4),
                       .energyUnderGravityOpen = randomCaseRange(-10.0, 1.38e-5),
                       .energyAbsolute = 1e-12,
                       .wallSlack = 0.0,
                       .ballOverlap = kRandomCaseMargin * 0.215,
                       .ballOverlapWithInteractions = kRandomCaseMargin * 0.175,
                       .wallOverlap = kRandomCaseMargin * 0.198},
        // None: its cost is fixed by the case (balls, steps, substeps), which drawCase bounds:
        // the default 2'000 cases take 3.5 s together.
        .workCap = {},
        .energyFinding = {},
        .determinismHash = 4657059805787966518u,
        .failureMap = kChipmunkBoundaries,
    },
    {
        .name = "bullet",
        // Bullet stores float (btScalar in Debian's default build) and, at its defaults, turns
        // shallow overlaps into real velocity (backends/bullet/split_impulse.h): its gas gains
        // energy, so the energy bounds are its measured changes, not rounding. Momentum 10× what
        // it measures (5.1e-7 of Σ m|v|: float rounding of ~900 collisions, as Box2D's). Energy
        // without gravity +176% in 5 s, under gravity +97%: both pinned, the first either way
        // within 20% (the field has one bound), the second with pinnedChange. Velocity 10× the
        // wall bounce's error, the largest (2.3e-5 of 3 m/s: the ball meets the wall 5.7e-6 m deep
        // at float rounding of 15.5 m, and the Baumgarte bias turns that into speed; the kicks and
        // setWorld's gravity are good to 3.6e-7). Position 10× the flight through a wall that is
        // off (5.3e-5 m after 120 float steps at 16–20 m, ulp 1.9e-6).
        .conformance = {.momentum = kClosedFormMargin * 5.14e-7,
                        .energy = 1.2 * 1.760,
                        .energyUnderGravity = pinnedChange(0.9708),
                        .velocity = kClosedFormMargin * 2.29e-5,
                        .position = kClosedFormMargin * 5.34e-5},
        // At its defaults the resting pile heats up (0 → 55 J of kinetic energy in 3 s) and hops,
        // and the gas's wall hits speed its balls up (the impulse says 1'869 bounces where the
        // paths at the start speed make 1'602): real motion, counted as such. Its counting is
        // checked with the knobs that stop that, as above.
        // With them the pile still warms (0.9 → 1.7 J over 2 s): 21.5 hops a second of 80 floor
        // balls; the gas's impulse says 0.75% more bounces than it counts (1'614 against the
        // paths' 1'602, which it counts exactly: the split impulse's push). Twice each.
        .wallCount = {.options = "split_impulse_penetration_threshold=0,contact_processing_"
                                 "threshold=0,warm_starting=0",
                      .restingPilePerSecond = 2.0 * 21.5,
                      .gasRelative = 2.0 * 0.0075},
        .methodError =
            {
                .timeStepped = true,
                .contactLag = 2.0,
                .wallLag = 2.0,
                .eulerFlight = true,
                .positionRoundingPerStep = 0x1p-21,
                .velocityRoundingPerStep = std::numeric_limits<float>::epsilon(),
            },
        // At its defaults the thermalised gas below gains a factor 2'500 in 45 s (the Baumgarte
        // push of every shallow overlap, backends/bullet/split_impulse.h) and the head-on and wall
        // hits come out faster or early: nothing to agree on. With issue #37's fix, the three knobs
        // at 0, it is a sequential-impulse method like Box2D.
        .consistencyOptions =
            "split_impulse_penetration_threshold=0,contact_processing_threshold=0,warm_starting=0",
        // With those, measured over this scene: +3.9e-3 at the end, +1.4e-3 on average (a gain: the
        // float state and the split impulse's push, which moves positions without paying for it);
        // three times the larger.
        .gasEnergyDrift = kGasDriftMargin * 3.92e-3,
        // Float state: a centre Bullet or the wall containment (backends/bullet/wall_containment.h)
        // puts on a face of a box up to 1'000 m high rounds to float by up to ½ ulp(1'000 m) =
        // 3.1e-5 m beyond it; the slack is that. Energy, twice the worst of the default cases
        // (kRandomCaseMargin), both ways, at Bullet's defaults: without gravity it gains up to 40%
        // (seed 1485: the Baumgarte push of shallow overlaps, backends/bullet/split_impulse.h)
        // and loses up to 42% (seed 1881; a contact solved before it touches can stop a ball dead,
        // contact_processing.h, but the case draws every option, so its cause is not singled
        // out); under gravity with ball collisions off −83% … +8.8%
        // (seeds 417, 962), with them on −99% … +149% (seeds 1764, 104), in an open box −10 times
        // the energy at the start (seed 268: semi-implicit Euler's fall) … +165% (seed 11). Below
        // −1 a loss bound bounds nothing; conformance pins its change under gravity instead.
        // Overlaps after resolved steps, the same margin: 0.215 of the smaller radius on its own
        // (seed 264, as Box2D and Chipmunk: Bullet finds contacts where a step starts, and its
        // split impulse removes 20% of an overlap a step), 0.160 with interactions (seed 1094), a
        // wall 0.197 of the radius (seed 125). The 2'000 cases take 23 s (shared 2-core VM).
        .robustness = {.energyWithoutGravity = randomCaseRange(-0.4244, 0.4039),
                       .energyUnderGravity = randomCaseRange(-0.8255, 0.08826),
                       .energyUnderGravityWithCollisions = randomCaseRange(-0.9871, 1.486),
                       .energyUnderGravityOpen = randomCaseRange(-10.02, 1.65),
                       .energyAbsolute = 1e-4,
                       .wallSlack = 3.1e-5,
                       .ballOverlap = kRandomCaseMargin * 0.2152,
                       .ballOverlapWithInteractions = kRandomCaseMargin * 0.1595,
                       .wallOverlap = kRandomCaseMargin * 0.1969},
        // None: its cost is fixed by the case (balls, steps, substeps, iterations), which drawCase
        // bounds.
        .workCap = {},
        .energyFinding = {},
        .determinismHash = 9457379961517678274u,
        .failureMap = kBulletBoundaries,
    },
    {
        .name = "matter",
        // matter.js as its users set it up (backends/js/adapters/matter.js), double state in
        // pixels (64 px/m) and pixels per 1/60 s frame. Its velocity is a difference of two
        // positions (Body.setVelocity: positionPrev = position − v), so a velocity set or kicked
        // keeps only the bits a position of a few hundred pixels leaves it: 10× the worst each
        // check measures, 1.6e-13 relative (the kick of SetBallEditsOneBall and the gravity of
        // SetWorldChangesGravityLive). Energy: its resting threshold (Resolver._restingThresh,
        // 2 px per frame, 1.9 m/s here) solves every slower contact as resting, without its
        // bounce: the 300-ball gas loses 30.2% in 5 s (measured), so 20% beyond that either way;
        // under gravity it loses 2.8%, pinned.
        .conformance = {.energy = 1.2 * 0.302,
                        .energyUnderGravity = pinnedChange(-0.02803),
                        .velocity = kClosedFormMargin * 1.6e-13},
        // At its defaults its resting threshold (2 px per frame, 1.9 m/s here) solves the gas's
        // 1 m/s wall hits as inelastic resting contacts: the balls stop at the walls (600 counted
        // where the paths make 1'602). Its counting is checked with the knob that stops that.
        // With it the pile's polygons settle into each other and stir (its potential energy falls
        // by 2 J in 3 s): 11.5 hops a second of 80 floor balls. Twice that.
        .wallCount = {.options = "resting_thresh=0", .restingPilePerSecond = 2.0 * 11.5},
        .methodError =
            {
                .timeStepped = true,
                // It finds a contact after the step's position update, reverses u in the
                // velocity pass and pushes the overlap out in the position pass of later steps
                // (factor 2, as Chipmunk).
                .contactLag = 2.0,
                .wallLag = 2.0,
                // Verlet on positions: v += g·dt, then x += v·dt (Body.update).
                .eulerFlight = true,
            },
        .consistencyOptions = "resting_thresh=0",
        // With resting_thresh=0 (consistencyOptions): measured +1.5e-13 at the end, +8.6e-14 on
        // average (rounding of its position differences); three times the larger.
        .gasEnergyDrift = kGasDriftMargin * 1.52e-13,
        // Its circles are what Bodies.circle makes: polygons of max(10, min(25, r in px)) sides,
        // 10-gons for this gas's 0.1 m balls (6.4 px), whose hits come closer than the circle's
        // 2r: measured 3.578 collisions per ball and second against 3.773–3.810 for elastic,
        // exact, xpbd and Box2D, −5.8% (the KS checks and Enskog's rate within 3% hold).
        .collisionRateOffset = -0.058,
        // The first 50 default cases (randomCases): each starts a Node.js process, 19 s together
        // on the loaded 2-core VM (all 2'000 would take 13 minutes). Energy, twice the worst of
        // them, both ways: the loss side bounds nothing, since resting_thresh is drawn up to
        // 100 px per frame (47 m/s), where every contact is solved as resting and inelastic; the
        // gain side is rounding without gravity (7.1e-11, seed 20: velocities of 1e-5 m/s kept
        // as differences of positions of a metre) and, under gravity with collisions off, the
        // position solver lifting balls it pushes out of the floor (2.5%, seed 4: slop 3.4 px).
        // Overlaps: none measured beyond the checks' zero in these cases.
        .robustness = {.energyWithoutGravity = randomCaseRange(-1.0, 7.12e-11),
                       .energyUnderGravity = randomCaseRange(-1.0, 0.0252),
                       .energyUnderGravityWithCollisions = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravityOpen = randomCaseRange(-10.0, 0.0),
                       .energyAbsolute = 1e-12,
                       .wallSlack = 0.0,
                       // The CLI's two-ball collision (cli_test) overlaps 0.0144 r: twice that.
                       .ballOverlap = kRandomCaseMargin * 0.0144,
                       .ballOverlapWithInteractions = 0.0,
                       .wallOverlap = 0.0},
        // Pure JavaScript in doubles: the same bits on every run (V8's Math.sin and Math.cos, which
        // build the circles' polygons, are its own fdlibm port, the same on every machine).
        .determinismHash = 8227773526849075201u,
        .failureMap = kMatterBoundaries,
        .randomCases = 50,
    },
    {
        .name = "rapier",
        // Rapier 2D 0.21.0 (the default `version`) as its users set it up
        // (backends/js/adapters/rapier.js): float state (f32, in WebAssembly) and soft contacts.
        // 10× what each check measures: momentum 9.0e-9 of Σ m|v| (float impulses); velocity
        // 6.0e-7 of the 1 m/s setWorld's gravity gives in 0.5 s (float steps); position 2.1e-4 m
        // after 2 s of flight at 3 m/s through a wall that is off (float positions at 20 m), as
        // Box2D. Energy: the soft contacts lose it (docs/accuracy.md): −13.4% of the 300-ball gas
        // in 5 s, so 20% beyond that either way, and −79.5% under gravity, pinned.
        .conformance = {.momentum = kClosedFormMargin * 9.0e-9,
                        .energy = 1.2 * 0.134,
                        .energyUnderGravity = pinnedChange(-0.795),
                        .velocity = kClosedFormMargin * 6.0e-7,
                        .position = kClosedFormMargin * 2.14e-4},
        .methodError =
            {
                .timeStepped = true,
                // Soft contacts reverse u over the step in which the overlap is found and push
                // the overlap out over later ones (factor 2, as Box2D).
                .contactLag = 2.0,
                .wallLag = 2.0,
                // Symplectic Euler (v += h·g; x += h·v).
                .eulerFlight = true,
                // float state: ½ ulp(8 … 16 m) = 2^−21 m, and ε = 2^−23.
                .positionRoundingPerStep = 0x1p-21,
                .velocityRoundingPerStep = std::numeric_limits<float>::epsilon(),
            },
        .gasStatisticsExemption =
            "its soft contacts drain the gas's energy (−31% in 10 s of the 2'000-ball gas) and no "
            "option stops it (docs/accuracy.md)",
        // The first 20 default cases (randomCases): each starts a Node.js process and loads the
        // WebAssembly, 81 s together on the loaded 2-core VM. Energy: the loss side bounds
        // nothing (its soft contacts and contact_natural_frequency, drawn up to 10 kHz), and no
        // case gained energy. Overlaps: bounds of 0.1 r between balls (0.2 r with tools) and
        // 0.05 r at walls that these cases stay within (a soft contact lets a ball in by the
        // allowed linear error; one case measured 2.8e-7 r at a wall); not tightened yet.
        .robustness = {.energyWithoutGravity = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravity = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravityWithCollisions = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravityOpen = randomCaseRange(-10.0, 0.0),
                       .energyAbsolute = 1e-4,
                       .wallSlack = 0.0,
                       .ballOverlap = 0.1,
                       .ballOverlapWithInteractions = 0.2,
                       .wallOverlap = 0.05},
        // WebAssembly without threads: the same bits on every run.
        .determinismHash = 11813233135854230608u,
        .failureMap = kRapierBoundaries,
        .randomCases = 20,
    },
    {
        .name = "box2d3",
        // Box2D v3 as its users set it up (backends/js/adapters/box2d3.js): float state (f32, in
        // WebAssembly) and soft contacts with relax iterations and a restitution pass. 10× what
        // each check measures: momentum 1.16e-8 of Σ m|v| (float impulses); velocity 6.0e-7 of the
        // 1 m/s setWorld's gravity gives in 0.5 s (float steps); position 5.3e-5 m after 2 s of
        // flight at 3 m/s through a wall that is off (float positions at 20 m). Energy: its solver
        // loses it at restitution 1 (docs/accuracy.md): −12.7% of the 300-ball gas in 5 s, so 20%
        // beyond that either way, and −78.8% under gravity, pinned.
        .conformance = {.momentum = kClosedFormMargin * 1.16e-8,
                        .energy = 1.2 * 0.127,
                        .energyUnderGravity = pinnedChange(-0.7878),
                        .velocity = kClosedFormMargin * 6.0e-7,
                        .position = kClosedFormMargin * 5.34e-5},
        // Its soft solver heats the pile a little (0.04 → 2 J of kinetic energy in 3 s): 3 hops a
        // second of 80 floor balls. Twice that.
        .wallCount = {.restingPilePerSecond = 2.0 * 3.0},
        .methodError =
            {
                .timeStepped = true,
                // It finds contacts, and takes their approach speeds for restitution, once a
                // step (its sub-steps play the Iterations role), so its solver step is the whole
                // step: it reverses u up to a step late and pushes the overlap out over later
                // ones (factor 2, as Box2D 2.4).
                .contactLag = 2.0,
                .wallLag = 2.0,
                // Symplectic Euler (v += h·g; x += h·v), the kicks and drag once a step.
                .eulerFlight = true,
                // float state: ½ ulp(8 … 16 m) = 2^−21 m, and ε = 2^−23.
                .positionRoundingPerStep = 0x1p-21,
                .velocityRoundingPerStep = std::numeric_limits<float>::epsilon(),
            },
        .gasStatisticsExemption = "its solver drains the gas's energy (−29.7% in 10 s of the "
                                  "2'000-ball gas at its users' "
                                  "settings) and no option stops it (docs/accuracy.md)",
        // The first 20 default cases (randomCases): each starts a Node.js process and loads the
        // WebAssembly, 37 s together on the loaded 2-core VM (a soak of 80 passes with the same
        // bounds in 76 s). Energy: the loss side bounds nothing (its solver, and the options drawn:
        // a restitution threshold up to 100 m/s makes every hit inelastic); the gain side is
        // twice the worst measured, +4.4% under gravity with collisions (seed 7: push_out_speed
        // 903 m/s and damping ratio 344 lift balls out of each other), none elsewhere. Overlaps,
        // twice the worst measured: 0.746 of the smaller radius between balls (seed 19) and 0.023
        // r at a wall (seed 4: a 6'137 Hz contact drawn against 8 sub-steps of 4.2 ms).
        .robustness = {.energyWithoutGravity = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravity = randomCaseRange(-1.0, 0.0),
                       .energyUnderGravityWithCollisions = randomCaseRange(-1.0, 0.0441),
                       .energyUnderGravityOpen = randomCaseRange(-10.0, 0.0),
                       .energyAbsolute = 1e-4,
                       .wallSlack = 0.0,
                       .ballOverlap = kRandomCaseMargin * 0.746,
                       .ballOverlapWithInteractions = 0.0,
                       .wallOverlap = kRandomCaseMargin * 0.0233},
        // WebAssembly without threads (pthreadCount 0): the same bits on every run.
        .determinismHash = 7550512406793700268u,
        .failureMap = kBox2d3Boundaries,
        .randomCases = 20,
    },
}};

}  // namespace

std::span<const BackendProfile> backendProfiles() {
  return kProfiles;
}

const BackendProfile& profileFor(std::string_view name) {
  for (const BackendProfile& profile : kProfiles) {
    if (profile.name == name) return profile;
  }
  throw std::logic_error("backend '" + std::string(name) +
                         "' has no row in tests/backend_profiles.cpp: state its tolerances there");
}

std::unique_ptr<Backend> createWithOptions(std::string_view name, std::string_view options) {
  RunSpec spec{std::string(name), {}};
  if (!options.empty()) spec = parseRunSpec(std::string(name).append(":").append(options));
  return createBackend(spec);
}

}  // namespace fooball::testing
