#pragma once

#include <chipmunk/chipmunk.h>

#include <span>

namespace fooball::chipmunk_detail {

/// Chipmunk's position correction, and why its defaults are wrong for balls in metres.
///
/// Chipmunk separates overlapping shapes with a bias velocity, kept apart from the real one (it
/// moves positions in the next step's position update and is then dropped, so it adds no kinetic
/// energy directly): for a contact whose shapes overlap by d, the bias closes
/// biasCoef·max(0, d − slop) in one step, with biasCoef = 1 − collisionBias^h (cpSpaceStep).
/// - collisionSlop defaults to 0.1, an absolute length meant for pixels. In metres it lets a
///   ball of radius 0.1 m overlap by its whole radius uncorrected, and it is not scale-free: the
///   failure map's scale sweep (1e-4 to 1e4 m) would see a different method at every scale. Here
///   the slop is a fraction of the smallest ball radius, converted to metres when the radii
///   change.
/// - collisionBias defaults to (1 − 0.1)^60: 10% of the overlap removed per 1/60 s step. The push
///   is not free: it lifts balls resting in a pile against gravity, and it moves two balls
///   apart that elasticity 1 is already flying apart, so they end farther apart than the
///   collision left them. Under gravity that is energy (potential energy gained without kinetic
///   energy paid), which the random invariants measure.
/// With elasticity 1 an isolated contact needs no correction at all: the impulse reverses the
/// approach speed u, and the next step flies the balls out of the overlap (at most u·h deep).
/// Only crowds (piles, jammed gases), where the iterative solver leaves some approach, sink in
/// for good without it. The defaults below are chosen from measurements (chipmunk_options.h).
inline constexpr double kDefaultSlopFraction = 0.05;
inline constexpr double kDefaultCollisionBias = 0.0018;
inline constexpr double kMaxSlopFraction = 0.5;

/// Sets the space's slop (m) from `slopFraction` of the smallest of `radii` (m), and its bias.
void setContactCorrection(cpSpace* space, std::span<const double> radii, double slopFraction,
                          double collisionBias);

}  // namespace fooball::chipmunk_detail
