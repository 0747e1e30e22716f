#pragma once

namespace fooball::bullet_detail {

/// Bullet's penetration recovery, and why at its default it *adds* energy with restitution 1.
///
/// Bullet finds a ball–ball contact only once the spheres overlap (discrete detection where a step
/// starts, on the positions the last one moved to), so every contact it solves starts with some
/// overlap d < 0. Its contact
/// row (btSequentialImpulseConstraintSolver::setupContactConstraint) removes the overlap with a
/// bias velocity −d·erp/h (Baumgarte stabilisation, erp 0.2 per step). Where that bias goes is
/// decided by btContactSolverInfo::m_splitImpulsePenetrationThreshold (default −0.04 m):
/// - an overlap shallower than it (d > −0.04 m, every overlap of a gas at ordinary speeds) has the
///   bias added to the restitution target of the same row: the push-out becomes real velocity, the
///   pair leaves faster than it came, and the kinetic energy grows with every contact;
/// - a deeper one is split: the bias goes into a separate push velocity, integrated into the
///   positions and then dropped (m_splitImpulse, on by default), so it moves the balls apart
///   without paying kinetic energy for it.
/// With restitution 1 nothing in the scene takes the added energy out again. Measured on the
/// standard gas (2'000 balls, 10 s, docs/accuracy.md): +726% at Bullet's defaults, −3.5% with this
/// threshold at 0 alone (what is left is the contact processing's loss, contact_processing.h),
/// +0.099% with the contact processing threshold at 0 too. The threshold is an absolute length,
/// 4 cm whatever the radii: the failure map's tunnelling sweep shows it (a 0.05 m ball's hit errs
/// while its first overlap is under 4 cm, and is exact beyond).
///
/// m, Bullet's default (btContactSolverInfo's constructor).
inline constexpr double kDefaultSplitImpulsePenetrationThreshold = -0.04;

}  // namespace fooball::bullet_detail
