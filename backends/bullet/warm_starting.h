#pragma once

namespace fooball::bullet_detail {

/// Bullet's warm starting: each contact point starts the solve of a step with
/// m_warmstartingFactor (default 0.85) of the impulse it ended the last step with, applied to the
/// bodies before the first iteration (setupContactConstraint, SOLVER_USE_WARMSTARTING, on by
/// default). For a resting stack that is what makes 10 iterations enough. For balls bouncing with
/// restitution 1 the impulse of a bounce is done in one step: the next step the pair is
/// separating, and the 0.85 of the last impulse it is given again must be taken back by the
/// iterations, which share it among the ball's other contacts in a crowd instead of removing it.
/// A factor of 0 starts every contact from nothing, as Box2D's velocity solver does with its
/// restitution pass. Here the factor is the knob (0 to 1); the flag stays on.
///
/// Bullet's default (btContactSolverInfo's constructor).
inline constexpr double kDefaultWarmstartingFactor = 0.85;

}  // namespace fooball::bullet_detail
