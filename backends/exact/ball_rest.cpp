// Balls resting on balls. As drag cools a pile under gravity, each ball's hops on the balls below
// it get ever shorter, and an event-driven solver must take every one: the collision rate grows
// without bound and a step never ends (issue 39: rain's 20th to 30th simulated second took 36 s
// of wall-clock, and 40 s were not reached in 600 s). Walls have their rest rule (bounce,
// layToRest); this is the rule for balls, after the sleeping islands of rigid-body engines and
// event-driven granular codes (a body below a speed threshold sleeps where it is held; a faster
// hit wakes it) and in the spirit of Luding & McNamara's TC model (a contact that would recur
// within t_c follows another rule). With t the option ball_rest_time, g = |gravity|,
// v_rest = g·t/2 (a hop at v_rest returns within t) and v_sleep = 2·v_rest:
//
// - Sleep: a ball no faster than v_sleep after an event, held against gravity by the walls and
//   sleeping balls it touches (within v_sleep²/2g, the height of a hop at v_sleep, and at most
//   r/10), stops where it is (laid onto a wall it presses on if rounding left it off by at most
//   1e-9·r): velocity 0, no gravity felt, no events of its own. Held is the frictionless balance of
//   one ball on fixed supports: "up" lies in the cone of the support normals (the floor; a pocket
//   between two balls; a ball and a side wall); a ball on one ball's flank is not held and slides
//   off. Energy: at most ½m·v_sleep² + m·|g|·1e-9·r (½m|v|² and the lay onto a wall), booked.
// - A moving ball meeting a sleeping one: it falls asleep if it may; a hit faster than the
//   pocket-escape speed √(2g(2 − √3)r) (wakeSpeed) wakes the sleeper (and, in turn, the
//   sleepers it alone held) and the two collide as moving balls; a slower hit cannot rearrange
//   the pile, which answers it as one body: the ball reflects off the sleeper as off a fixed
//   wall, leaving at max(u, v_rest) (u its approach speed), and the walls take the impulse
//   (wallImpulse). Energy: ½m(max(u, v_rest)² − u²) ≤ ½m·v_rest², booked.
// - Two moving balls that feel different gravity (one rests on a wall) leave a contact at a
//   normal speed of at least |Δg|·t/2, momentum conserved. Without it a pair pressed together
//   by its relative gravity and not approaching is predicted to touch again at once, for ever:
//   each event must change the state so that the same pair is not met again at that instant.
//   Energy: ½μ(w² − u²) ≤ ½μ(|Δg|·t/2)², booked (μ the reduced mass).
//   The kicks leave at v_rest and a ball sleeps at up to 2·v_rest, so a ball hopping on
//   sleepers after a kick can fall asleep at its next contact rather than be kicked for ever.
// - Pairs under the same gravity fly straight relative to each other and no rule touches
//   them, so every result where no ball rests is the same bit for bit.
// - Waking: a hit faster than the pocket-escape speed, a force (a mouse tool), and anything that
//   rebuilds the calendar (an edit, a change of the world or of this option, a cut-short step),
//   which wakes every ball; they fall asleep again at their next events where still held and
//   slow.
// - Cost: a sleeping ball has no events; a moving ball's search for its contact with a sleeping
//   neighbour (a curved relative path, acceleratedPairContact) stops at the ball's next cell
//   crossing, where it is predicted afresh.
// Every rule is arithmetic on the state in event order: deterministic.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "event_driven_world.h"

namespace fooball::exact {

namespace {

/// A support counts within a hop at the sleep speed, but never beyond this many of the ball's
/// radius: a long rest time under strong gravity must not hold balls in mid-air.
constexpr double kSupportGapRadii = 0.1;
/// Rounding's share of a radius: a sleeping ball this close to a wall is laid onto it.
constexpr double kLayGapRadii = 1e-9;

}  // namespace

void EventDrivenWorld::updateRestScales() {
  const double gravity = length(world_.gravity);
  restSpeed_ = 0.5 * gravity * limits_.ballRestTime;
  sleepSpeed_ = 2.0 * restSpeed_;
  supportGap_ = gravity > 0.0 ? sleepSpeed_ * sleepSpeed_ / (2.0 * gravity) : 0.0;
}

/// m/s, the slowest hit that wakes `sleeper`: one that could lift it out of a hexagonal pocket of
/// balls its size, by (2 − √3)·r, if it took the whole approach speed (an equal mass does).
/// Slower hits leave the pile's arrangement standing, so the pile answers them as one body.
double EventDrivenWorld::wakeSpeed(std::uint32_t sleeper) const {
  constexpr double kPocketDepth = 2.0 - std::numbers::sqrt3;  // radii
  return std::sqrt(2.0 * length(world_.gravity) * kPocketDepth * balls_[sleeper].radius);
}

void EventDrivenWorld::setRestBits(std::uint32_t ball, std::uint8_t bits) {
  std::uint8_t& restingOn = restingOn_[ball];
  if (restingOn == 0 && bits != 0) ++restingCount_;
  if (restingOn != 0 && bits == 0) --restingCount_;
  restingOn = bits;
}

/// m/s, the least normal speed at which `first` and `second` (touching) leave their contact:
/// |Δg|·t/2 where they feel different gravity, so a pressed pair's next contact is about t away.
double EventDrivenWorld::restKick(std::uint32_t first, std::uint32_t second) const {
  if (restingCount_ == 0 || limits_.ballRestTime == 0.0) return 0.0;
  return 0.5 * length(gravityOf(second) - gravityOf(first)) * limits_.ballRestTime;
}

/// The impulse between two touching moving balls (advanced to now).
void EventDrivenWorld::exchange(std::uint32_t first, std::uint32_t second) {
  BallMotion& a = balls_[first];
  BallMotion& b = balls_[second];
  const Vec2 separation = b.position - a.position;
  const double distance = std::sqrt(lengthSquared(separation));  // no overflow at box scales
  if (!(distance > 0.0)) return;
  const Vec2 normal = separation / distance;
  const double approach = dot(b.velocity - a.velocity, normal);  // < 0: closing
  const double kick = restKick(first, second);
  const double totalMass = mass_[first] + mass_[second];
  if (kick > std::abs(approach)) {
    // They leave at `kick` instead of |approach|: Δu = kick − approach, shared as momentum asks.
    const double change = kick - approach;
    a.velocity -= (change * (mass_[second] / totalMass)) * normal;
    b.velocity += (change * (mass_[first] / totalMass)) * normal;
    const double reducedMass = mass_[first] * (mass_[second] / totalMass);
    statistics_.restEnergyChange += 0.5 * reducedMass * (kick * kick - approach * approach);
    statistics_.restEnergyBound += 0.5 * reducedMass * kick * kick;
  } else if (approach < 0.0) {
    // Δv_a = 2·m_b/(m_a + m_b)·u_n·n and the mirror image: each weight is its own quotient
    // (never 1 − the other), so the light ball's change keeps full precision and the heavy
    // one's is tiny but exact, at any mass ratio.
    a.velocity += (2.0 * approach * (mass_[second] / totalMass)) * normal;
    b.velocity -= (2.0 * approach * (mass_[first] / totalMass)) * normal;
  } else {
    return;
  }
  ++counters_.ballCollisions;
  ++statistics_.collisionsThisStep;
}

/// Whether the walls and sleeping balls the ball (advanced to now) touches, within supportGap_,
/// hold it against gravity without friction: "up" lies in the cone of their normals. In 2D that
/// is a normal straight up, or one on each side of up less than a half turn apart.
bool EventDrivenWorld::held(std::uint32_t ball) const {
  const BallMotion& motion = balls_[ball];
  const Vec2 up = -world_.gravity / length(world_.gravity);
  // The angle (rad) from up to the nearest support normal on each side, +π if none.
  double left = std::numbers::pi;
  double right = std::numbers::pi;
  bool straightUp = false;
  const auto support = [&](Vec2 normal) {
    const double angle = std::atan2(up.x * normal.y - up.y * normal.x, dot(up, normal));
    if (angle == 0.0) straightUp = true;
    if (angle > 0.0) left = std::min(left, angle);
    if (angle < 0.0) right = std::min(right, -angle);
  };
  for (int side = 0; side < 4; ++side) {
    const Side wall = static_cast<Side>(side);
    if (!wallOn(wall)) continue;
    const int axis = axisOf(wall);
    const double inward = isLowerSide(wall) ? 1.0 : -1.0;
    const double gap =
        inward * (component(motion.position, axis) - contactCoordinate(wall, motion.radius));
    if (gap > std::min(supportGap_, kSupportGapRadii * motion.radius)) continue;
    Vec2 normal;
    componentRef(normal, axis) = inward;
    support(normal);
  }
  cells_.forEachNeighbour(ball, [&](std::uint32_t other) {
    if (!asleep(other)) return;
    const Vec2 separation = motion.position - balls_[other].position;
    const double distance = length(separation);
    if (distance - (motion.radius + balls_[other].radius) >
            std::min(supportGap_, kSupportGapRadii * motion.radius) ||
        !(distance > 0.0))
      return;
    support(separation / distance);
  });
  return straightUp || left + right < std::numbers::pi;
}

/// Puts the ball (advanced to now) to sleep where it is, if it is slow and held. A wall that
/// gravity presses it on and that rounding left it off (within kLayGapRadii of its radius) lays
/// it onto the wall, as layToRest; further off it sleeps where it is, since moving it could press
/// it into a neighbour. The caller predicts it again.
bool EventDrivenWorld::trySleep(std::uint32_t ball) {
  if (!sleepActive() || asleep(ball)) return false;
  BallMotion& motion = balls_[ball];
  const double speedSquared = lengthSquared(motion.velocity);
  if (speedSquared > sleepSpeed_ * sleepSpeed_ || !held(ball)) return false;
  const double mass = mass_[ball];
  statistics_.restEnergyChange -= 0.5 * mass * speedSquared;
  const double beforeLay = statistics_.restEnergyChange;
  ++statistics_.sleeps;
  motion.velocity = {};
  for (int side = 0; side < 4; ++side) {
    const Side wall = static_cast<Side>(side);
    const int axis = axisOf(wall);
    const double inward = isLowerSide(wall) ? 1.0 : -1.0;
    const double gap =
        inward * (component(motion.position, axis) - contactCoordinate(wall, motion.radius));
    if (wallOn(wall) && gap <= kLayGapRadii * motion.radius &&
        inward * component(world_.gravity, axis) < 0.0)
      layToRest(ball, wall);
  }
  // ½m·v_sleep², and what the lay onto a wall changed (m·|g|·1e-9·r at most).
  statistics_.restEnergyBound +=
      0.5 * mass * sleepSpeed_ * sleepSpeed_ + std::abs(statistics_.restEnergyChange - beforeLay);
  ++motion.version;
  setRestBits(ball, static_cast<std::uint8_t>(restingOn_[ball] | kAsleep));
  return true;
}

/// `mover` (moving) meets `sleeper`, both advanced to now: see the top of the file.
void EventDrivenWorld::meetSleeper(std::uint32_t mover, std::uint32_t sleeper) {
  BallMotion& motion = balls_[mover];
  const Vec2 separation = motion.position - balls_[sleeper].position;
  const double distance = std::sqrt(lengthSquared(separation));
  const Vec2 normal =
      distance > 0.0 ? separation / distance : -world_.gravity / length(world_.gravity);
  const double approach = -dot(motion.velocity, normal);  // m/s, > 0: closing
  if (!trySleep(mover)) {
    if (approach > wakeSpeed(sleeper)) {
      wake(sleeper);
      exchange(mover, sleeper);
      liftIfMoving(sleeper);
    } else {
      const double leave = std::max(approach, restSpeed_);
      const double mass = mass_[mover];
      motion.velocity += (approach + leave) * normal;
      counters_.wallImpulse += mass * (approach + leave);
      statistics_.restEnergyChange += 0.5 * mass * (leave * leave - approach * approach);
      statistics_.restEnergyBound += 0.5 * mass * restSpeed_ * restSpeed_;
      ++counters_.ballCollisions;
      ++statistics_.collisionsThisStep;
    }
    ++motion.version;
    liftIfMoving(mover);
  }
  predict(mover);
  predictWoken();
}

/// The sleeping ball moves again, and so do the sleeping balls touching it that it alone held,
/// in turn; predictWoken() predicts them all once the event is done.
void EventDrivenWorld::wake(std::uint32_t ball) {
  const auto rouse = [this](std::uint32_t sleeper) {
    advance(sleeper, now_);  // books the weight its supports carried up to now
    setRestBits(sleeper, static_cast<std::uint8_t>(restingOn_[sleeper] & ~kAsleep));
    ++balls_[sleeper].version;
    ++statistics_.wakes;
    woken_.push_back(sleeper);
  };
  const std::size_t first = woken_.size();
  rouse(ball);
  for (std::size_t next = first; next < woken_.size(); ++next) {
    const BallMotion& woken = balls_[woken_[next]];
    cells_.forEachNeighbour(woken_[next], [&](std::uint32_t other) {
      if (!asleep(other)) return;
      const double gap =
          length(balls_[other].position - woken.position) - (woken.radius + balls_[other].radius);
      if (gap <= std::min(supportGap_, kSupportGapRadii * balls_[other].radius) && !held(other))
        rouse(other);
    });
  }
}

void EventDrivenWorld::predictWoken() {
  for (std::uint32_t ball : woken_)
    predict(ball);
  woken_.clear();
}

}  // namespace fooball::exact
