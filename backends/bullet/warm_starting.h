#pragma once

namespace fooball::bullet_detail {

/// Bullet's warm starting: each contact point starts the solve of a step with
/// m_warmstartingFactor (default 0.85) of the impulse it ended the last step with, applied to the
/// bodies before the first iteration (setupContactConstraint, SOLVER_USE_WARMSTARTING, on by
/// default). For a resting stack that is what makes 10 iterations enough; for bouncing balls it
/// carries a bounce's impulse into the next step, where the iterations must take it back. Measured
/// on the standard gas (docs/accuracy.md), it changes little: +721% with the factor at 0 against
/// +726% at Bullet's defaults, and nothing to three digits once the split-impulse and contact
/// processing thresholds are at 0 (+0.099% either way). It is an option because bullet3#3094's
/// answer sets it to 0. Here the factor is the knob (0 to 1); the flag stays on.
///
/// Bullet's default (btContactSolverInfo's constructor).
inline constexpr double kDefaultWarmstartingFactor = 0.85;

}  // namespace fooball::bullet_detail
