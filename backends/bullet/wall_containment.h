#pragma once

#include <btBulletDynamicsCommon.h>

#include <cstdint>

#include "common/wall_mirror.h"
#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::bullet_detail {

/// Brings back a ball whose centre a Bullet step left beyond a wall that is on, as an elastic wall
/// would have: its centre mirrored in the wall's face, its velocity across the wall turned inwards.
///
/// Bullet finds contacts where a step starts (btDiscreteDynamicsWorld's
/// performDiscreteCollisionDetection runs before the solve and the motion), so a ball more than
/// its step's travel from a wall ends the step with its centre beyond the wall when it is fast
/// (the conformance suite's fast gas: 45 m/s, 0.3 m from a wall, in its first frame). A plane is
/// a half-space (wall_planes.h) and would push it back over the next steps, but the contract keeps
/// every centre inside the box after every step. Bullet's own cure is continuous collision
/// (setCcdMotionThreshold, setCcdSweptSphereRadius), off by default, and it brings more than the
/// walls need: it sweeps every fast ball against every ball too and solves each hit as a
/// speculative contact with restitution 0 (createPredictiveContactsInternal), and it frees and
/// grows its array of those contacts every step (releasePredictiveContacts), so it is left at its
/// default. The returns are counted (diagnostic `balls_brought_back`).
///
/// The mirror and its energy are common::WallMirror's. A ball whose velocity still pointed out of
/// the box bounced here, not in Bullet: that bounce is counted with its impulse, as every wall
/// collision only when the ball did not touch that wall already (common/wall_touches.h). The same
/// pass forgets the walls each ball has left.
class WallContainment {
 public:
  /// `gravity` (m/s²) as the step flies the balls.
  WallContainment(const Box& box, const Walls& walls, Vec2 gravity);

  /// Brings `ball` (mass in kg, radius in m) back if its centre is beyond a wall; `touches` are
  /// the walls it touches.
  void contain(btRigidBody& ball, double mass, double radius, common::WallTouches& touches) {
    const btVector3& p = ball.getWorldTransform().getOrigin();
    const Vec2 centre{static_cast<double>(p.x()), static_cast<double>(p.y())};
    if (touches != 0) touches = common::stillTouching(touches, centre, radius, box_);
    if (mirror_.inside(centre.x, centre.y)) return;
    bringBack(ball, mass, touches);
  }

  std::uint64_t ballsBroughtBack() const { return ballsBroughtBack_; }
  std::uint64_t wallCollisions() const { return wallCollisions_; }  ///< unseen by Bullet
  double impulse() const { return impulse_; }  ///< N·s, Σ|Δp| of the velocities turned back

 private:
  void bringBack(btRigidBody& ball, double mass, common::WallTouches& touches);

  Box box_;
  common::WallMirror mirror_;
  std::uint64_t ballsBroughtBack_ = 0;
  std::uint64_t wallCollisions_ = 0;
  double impulse_ = 0.0;
};

}  // namespace fooball::bullet_detail
