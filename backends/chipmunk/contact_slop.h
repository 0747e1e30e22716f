#pragma once

#include <chipmunk/chipmunk.h>

#include <span>

namespace fooball::chipmunk_detail {

/// Chipmunk's position correction, and why its defaults are wrong for balls in metres.
///
/// Chipmunk separates overlapping shapes with a bias velocity, kept apart from the real one (it
/// moves positions in the next step's position update and is then dropped, so it adds no kinetic
/// energy directly): for a contact whose shapes overlap by d, the bias closes
/// biasCoef·max(0, d − slop) in one step, with biasCoef = 1 − collisionBias^h (cpSpaceStep,
/// cpArbiterPreStep).
/// - collisionSlop defaults to 0.1, an absolute length meant for pixels. In metres it lets a
///   ball of radius 0.1 m overlap by its whole radius uncorrected, and it is not scale-free: the
///   failure map's scale sweep (1e-4 to 1e4 m) would see a different method at every scale. Here
///   the slop is a fraction of the smallest ball radius, converted to metres when the radii
///   change.
/// - collisionBias defaults to (1 − 0.1)^60 ≈ 0.0018: 10% of the overlap removed per 1/60 s.
///   The push moves positions without paying for it in kinetic energy, so under gravity it adds
///   potential energy, which is why it is suspected of adding energy. But the overlap it removes
///   is potential energy the balls lost by sinking into each other in the first place: a pile
///   whose overlaps linger sits lower than the exact one, and the energy it "lost" returns only
///   when the overlap is pushed out.
///
/// The defaults chosen here are no slop and no overlap left after the next step (bias 0 makes
/// biasCoef = 1). Measured with 4 substeps (chipmunk_options.h), against Chipmunk-like values
/// (slop 5% of the radius, bias 0.0018) and the pair's halves (`fooball-cli failure-map --sweep
/// pile`, full grid; `fooball-cli compare --duration 20` on the presets):
/// - resting pile of 22 balls, energy error / Σ m·g·r at g = 1, 10, 31.6 m/s²:
///   6.6e-4, 7.5e-3, 0.022 here; 0.040, 0.10, 0.21 with slop 5% and bias 0.0018 (the pile sinks
///   by the slop, 0.042 r); 3.8e-3, 0.039, 0.12 with slop 0 and bias 0.0018. It holds up to
///   31.6 m/s² here, to 3.16 with the Chipmunk-like values;
/// - energy change after 20 s: preset `default` −4.6% here, −7.7% Chipmunk-like; `rain` −3.8%
///   and −6.1%; `dense` −0.12% and −0.13%; `gas` −1.3e-7 and −1.2e-7;
/// - the price, in a gas: the standard gas of 2'000 balls over 600 steps (docs/performance.md)
///   loses 2.4e-5 here against 1.2e-5 Chipmunk-like, and at one substep 6.7e-4 against 1.5e-4.
///   Balls pushed fully apart meet their next neighbours at other times; measured, not derived;
/// - random invariants (tests/robustness): no case gains more energy with these than with the
///   Chipmunk-like values (worst 7.5e-4 and 7.8e-4, of 2'000 cases).
/// A full correction can overshoot where one ball has many contacts (the iterations correct each
/// contact in turn), but a bias velocity never enters the real velocity, so an overshoot shows as
/// a position jitter within one overlap, not as energy.
inline constexpr double kDefaultSlopFraction = 0.0;
inline constexpr double kDefaultCollisionBias = 0.0;
inline constexpr double kMaxSlopFraction = 0.5;

/// Sets the space's slop (m) from `slopFraction` of the smallest of `radii` (m), and its bias.
void setContactCorrection(cpSpace* space, std::span<const double> radii, double slopFraction,
                          double collisionBias);

}  // namespace fooball::chipmunk_detail
