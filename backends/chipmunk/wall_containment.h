#pragma once

#include <chipmunk/chipmunk.h>

#include <cstdint>

#include "common/wall_mirror.h"
#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::chipmunk_detail {

/// Brings back a ball whose centre a Chipmunk step left beyond a wall that is on, as an elastic
/// wall would have: its centre mirrored in the wall's face, its velocity into the wall reflected.
///
/// Chipmunk has no continuous collision: it finds contacts only where a step ends, so a ball
/// that moves more than its radius plus the wall's thickness past the face in one step
/// (wall_segments.h) has its centre beyond the wall's axis and is pushed out on the far side,
/// lost for good. The random invariants (tests/robustness) throw exactly that at it (speeds up to
/// 5 box sides per second, steps up to 50 ms, balls down to 1e-5 of the box). Every ball inside
/// the box passes four comparisons; one whose centre crossed a face is brought back at once,
/// before anyone reads it or the next step finds its contacts. A ball whose centre is beyond the
/// face by less went through Chipmunk's own contact, whose impulse already turned it inwards: it
/// is only mirrored. A resting contact never gets this deep: the slop (contact_slop.h) is at most
/// half the smallest radius.
///
/// The mirror and its energy are common::WallMirror's. The bounce is counted as a wall
/// collision only when Chipmunk cannot have seen it: a centre more than radius + 2·thickness
/// beyond the face was beyond the wall's reach, so no contact began (contact_counter.h); and, as
/// every wall collision, only when the ball did not touch that wall already
/// (common/wall_touches.h). The same pass forgets the walls each ball has left.
class WallContainment {
 public:
  /// `gravity` (m/s²) as the step flies the balls; `thickness` (m) of the walls.
  WallContainment(const Box& box, const Walls& walls, Vec2 gravity, double thickness);

  /// Brings `ball` (radius in m, mass in kg) back if its centre is beyond a wall; `touches`
  /// are the walls it touches.
  void contain(cpBody* ball, double radius, double mass, common::WallTouches& touches) {
    const cpVect p = cpBodyGetPosition(ball);
    if (touches != 0) touches = common::stillTouching(touches, {p.x, p.y}, radius, box_);
    if (mirror_.inside(p.x, p.y)) return;
    bringBack(ball, radius, mass, touches);
  }

  std::uint64_t ballsBroughtBack() const { return ballsBroughtBack_; }
  std::uint64_t wallCollisions() const { return wallCollisions_; }  ///< unseen by Chipmunk
  double impulse() const { return impulse_; }  ///< N·s, Σ|Δp| of the velocities turned back

 private:
  void bringBack(cpBody* ball, double radius, double mass, common::WallTouches& touches);

  Box box_;
  common::WallMirror mirror_;
  double thickness_;  ///< m
  std::uint64_t ballsBroughtBack_ = 0;
  std::uint64_t wallCollisions_ = 0;
  double impulse_ = 0.0;
};

}  // namespace fooball::chipmunk_detail
