#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_common.h>

#include <cstdint>

#include "fooball/scene.h"

namespace fooball::box2d_detail {

/// m: how far beyond a wall's face Box2D itself may leave a ball's centre. Its continuous
/// collision stops a ball against a static body with up to 3 linear slops of overlap plus a
/// tolerance of a quarter slop (b2TimeOfImpact: target separation r − 3·slop, tolerance
/// slop/4; the walls' skin is accounted for in wall_bodies.cpp), so a ball smaller than that may
/// rest with its centre up to 3.25 slops beyond the face. Never more, while the continuous
/// collision works.
inline constexpr double kWallSlack = 3.25 * static_cast<double>(b2_linearSlop);

/// Puts back a ball whose centre lies beyond a wall that is on by more than kWallSlack: its
/// centre on the wall's face, the velocity component into the wall reflected, as an elastic wall
/// would. Box2D's continuous collision gives up in crowds: a time-of-impact sub-step corrects the
/// positions of the two balls that hit without the walls they do not touch yet, which can push a
/// ball's centre into a wall, and b2TimeOfImpact then finds the ball already overlapping the wall
/// and stops looking (b2TOIOutput::e_overlapped); a contact also stops after b2_maxSubSteps
/// sub-steps in one Box2D step, which a tiny ball lying against a wall uses up at once. Such a
/// ball ends the step deep in the wall, and can get deeper than the walls' thickness is made for
/// (wall_bodies.cpp): pushed out through a piece's end or the far side, it is lost. The random
/// invariants (tests/robustness) found this in 13 of 10'000 cases, all with bullets on: centres
/// up to 2.5 m beyond a wall, and two balls lost for good (one stuck in a corner of the walls,
/// one pushed out 12 m beyond them).
///
/// Run by the velocity scan after every Box2D step (velocity_scan.h), in the same pass over the
/// bodies: a second pass would load every b2Body again.
class WallContainment {
 public:
  WallContainment(const Box& box, const Walls& walls);

  /// Puts `ball` (mass in kg) back if it is beyond a wall; returns its velocity, reflected if so.
  /// Inline, and only four comparisons for a ball inside: it runs for every ball and Box2D step.
  b2Vec2 contain(b2Body& ball, double mass) {
    const b2Vec2& p = ball.GetPosition();
    const double x = static_cast<double>(p.x);
    const double y = static_cast<double>(p.y);
    if (x >= lowest_.x && x <= highest_.x && y >= lowest_.y && y <= highest_.y)
      return ball.GetLinearVelocity();
    return putBack(ball, mass);
  }

  std::uint64_t ballsPutBack() const { return ballsPutBack_; }
  double impulse() const { return impulse_; }  ///< N·s, Σ|Δp| of the velocities turned back

 private:
  b2Vec2 putBack(b2Body& ball, double mass);

  Box box_;
  Vec2 lowest_;   ///< m, the lowest centre left alone (−∞ where a wall is off)
  Vec2 highest_;  ///< m, the highest
  std::uint64_t ballsPutBack_ = 0;
  double impulse_ = 0.0;
};

}  // namespace fooball::box2d_detail
