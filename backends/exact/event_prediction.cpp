#include <algorithm>
#include <cmath>
#include <limits>

#include "barrier_contact.h"
#include "event_driven_world.h"
#include "free_flight.h"
#include "pair_contact.h"

namespace fooball::exact {

void EventDrivenWorld::predict(std::uint32_t ball) {
  advance(ball, now_);
  Event next;
  if (asleep(ball)) {
    // A sleeping ball holds no events: its contacts go to the moving balls around it.
    schedule_[ball].crossing = {};
    cells_.forEachNeighbour(ball, [&](std::uint32_t other) { checkPair(ball, other, next); });
    setInteraction(ball, next);
    return;
  }
  for (int side = 0; side < 4; ++side) {
    const Side wall = static_cast<Side>(side);
    if (wallReachable(ball, wall)) keepEarlier(next, wallContact(ball, wall));
  }
  if (cellsActive_) {
    schedule_[ball].crossing = nextCellCrossing(ball);
    cells_.forEachNeighbour(ball, [&](std::uint32_t other) { checkPair(ball, other, next); });
  }
  setInteraction(ball, next);
}

/// The ball's motion is unchanged by a crossing, so its interaction event stands (or, if its
/// partner has changed since, is caught when it comes due); only the cells that have just come
/// within reach need checking.
void EventDrivenWorld::crossCell(std::uint32_t ball, Side side) {
  advance(ball, now_);
  cells_.cross(ball, side);
  schedule_[ball].crossing = nextCellCrossing(ball);
  Event next = schedule_[ball].interaction;
  if (wallReachable(ball, side)) keepEarlier(next, wallContact(ball, side));
  cells_.forEachNewNeighbour(ball, side,
                             [&](std::uint32_t other) { checkPair(ball, other, next); });
  setInteraction(ball, next);
}

/// With cells, a ball can touch a wall only from the row or column of cells along it (cells are
/// wider than any radius), so walls are checked there only.
bool EventDrivenWorld::wallReachable(std::uint32_t ball, Side wall) const {
  if (cellsActive_) {
    const int axis = axisOf(wall);
    const int cell = axis == 0 ? cells_.columnOf(ball) : cells_.rowOf(ball);
    if (isLowerSide(wall) ? cell != 0 : cell + 1 != cells_.cellCount(axis)) return false;
  }
  return wallOn(wall);
}

Event EventDrivenWorld::wallContact(std::uint32_t ball, Side wall) const {
  const BallMotion& motion = balls_[ball];
  const int axis = axisOf(wall);
  if (restsAlong(ball, axis)) return {};               // fixed along this axis
  const double sign = isLowerSide(wall) ? 1.0 : -1.0;  // the gap grows with sign·x
  const double delay = firstBarrierContact(
      sign * (component(motion.position, axis) - contactCoordinate(wall, motion.radius)),
      sign * component(motion.velocity, axis), sign * component(gravityOf(ball), axis),
      world_.airResistance);
  return {now_ + delay, 0, static_cast<std::uint32_t>(wall), EventKind::Wall};
}

CellCrossing EventDrivenWorld::nextCellCrossing(std::uint32_t ball) const {
  return straightFlight() ? straightCellCrossing(ball) : curvedCellCrossing(ball);
}

CellCrossing EventDrivenWorld::curvedCellCrossing(std::uint32_t ball) const {
  const BallMotion& motion = balls_[ball];
  const Vec2 gravity = gravityOf(ball);
  CellCrossing next;
  for (int axis = 0; axis < 2; ++axis) {
    if (restsAlong(ball, axis)) continue;
    const double coordinate = component(motion.position, axis);
    const double rate = component(motion.velocity, axis);
    const double acceleration = component(gravity, axis);
    const int cell = axis == 0 ? cells_.columnOf(ball) : cells_.rowOf(ball);
    // Border cells reach to infinity outwards: no face there.
    if (cell > 0) {
      const double delay = firstBarrierContact(coordinate - cells_.lowerFace(axis, cell), rate,
                                               acceleration, world_.airResistance);
      if (now_ + delay < next.time) next = {now_ + delay, lowerSide(axis)};
    }
    if (cell + 1 < cells_.cellCount(axis)) {
      const double delay = firstBarrierContact(cells_.upperFace(axis, cell) - coordinate, -rate,
                                               -acceleration, world_.airResistance);
      if (now_ + delay < next.time) next = {now_ + delay, upperSide(axis)};
    }
  }
  return next;
}

/// curvedCellCrossing in straight flight: firstBarrierContact with no acceleration and no drag
/// reduces to gap / closing speed for the face the ball moves towards (0 if rounding left it on
/// or past that face), and never for the face behind it.
CellCrossing EventDrivenWorld::straightCellCrossing(std::uint32_t ball) const {
  const BallMotion& motion = balls_[ball];
  CellCrossing next;
  for (int axis = 0; axis < 2; ++axis) {
    const double coordinate = component(motion.position, axis);
    const double rate = component(motion.velocity, axis);
    const int cell = axis == 0 ? cells_.columnOf(ball) : cells_.rowOf(ball);
    double gap;
    Side face;
    if (rate < 0.0) {
      if (cell == 0) continue;  // border cells reach to infinity outwards
      gap = coordinate - cells_.lowerFace(axis, cell);
      face = lowerSide(axis);
    } else if (rate > 0.0) {
      if (cell + 1 == cells_.cellCount(axis)) continue;
      gap = cells_.upperFace(axis, cell) - coordinate;
      face = upperSide(axis);
    } else {
      continue;
    }
    const double delay = gap <= 0.0 ? 0.0 : gap / std::abs(rate);
    if (now_ + delay < next.time) next = {now_ + delay, face};
  }
  return next;
}

/// Predicts the contact of `ball` (advanced to now) with `other`. If it comes before `next`,
/// it becomes the ball's next interaction; if before the other's, the other's too, so each
/// ball's interaction event stays its earliest. The event it displaces there needs no removal:
/// its own partner's version check, or a fresh prediction when it comes due, catches it.
void EventDrivenWorld::checkPair(std::uint32_t ball, std::uint32_t other, Event& next) {
  if (asleep(ball) && asleep(other)) return;  // two sleeping balls never meet
  if (straightFlight()) {
    checkStraightPair(ball, other, next);
  } else {
    checkCurvedPair(ball, other, next);
  }
}

/// checkCurvedPair with decay = 1, s = τ and g = 0, kept small for the common gas.
void EventDrivenWorld::checkStraightPair(std::uint32_t ball, std::uint32_t other, Event& next) {
  const BallMotion& motion = balls_[ball];
  const BallMotion& partner = balls_[other];
  const Vec2 separation =
      (partner.position - motion.position) + (now_ - partner.time) * partner.velocity;
  const double delay = linearContactParameter(separation, partner.velocity - motion.velocity,
                                              motion.radius + partner.radius);
  if (delay == std::numeric_limits<double>::infinity()) return;
  schedulePair(ball, other, next, now_ + delay, EventKind::Pair);
}

/// The general case: both balls fly under gravity and drag (free_flight.h); their relative path
/// is curved only when they feel different gravity (one rests on a wall).
void EventDrivenWorld::checkCurvedPair(std::uint32_t ball, std::uint32_t other, Event& next) {
  const BallMotion& motion = balls_[ball];
  const BallMotion& partner = balls_[other];
  const double drag = world_.airResistance;
  const FlightFactors flight = flightFactors(drag, now_ - partner.time);
  const Vec2 gravity = gravityOf(ball);
  const Vec2 partnerGravity = gravityOf(other);
  const PairMotion pair{(partner.position - motion.position) +
                            flightDisplacement(partner.velocity, partnerGravity, flight),
                        flightVelocity(partner.velocity, partnerGravity, flight) - motion.velocity,
                        partnerGravity - gravity, motion.radius + partner.radius};
  EventKind kind = EventKind::Pair;
  double delay;
  if (partnerGravity == gravity) {
    delay = timeForFlightParameter(
        drag, linearContactParameter(pair.separation, pair.relativeVelocity, pair.reach));
  } else {
    // Each ball predicts again at its own next event, so the search need not look past the
    // later of the two. Against a sleeping ball, which has no events, it need not look past
    // the moving ball's next cell crossing either, if a fresh prediction is due there: a
    // search along an open horizon costs up to kMaxSteps, and a ball in a sleeping pile has
    // several sleeping neighbours it may never touch.
    double end = std::max(next.time, partner.interactionTime);
    double crossing = std::numeric_limits<double>::infinity();
    if (asleep(other)) {
      end = next.time;
      crossing = schedule_[ball].crossing.time;
    } else if (asleep(ball)) {
      end = partner.interactionTime;
      crossing = schedule_[other].crossing.time;
    }
    const bool recheckAtCrossing = crossing > now_ && crossing < end;
    const double horizon = (recheckAtCrossing ? crossing : end) - now_;
    const PairContact contact = acceleratedPairContact(pair, drag, horizon);
    if (contact.kind == PairContactKind::None && !recheckAtCrossing) return;
    if (contact.kind != PairContactKind::Contact) kind = EventKind::Recheck;
    if (contact.kind == PairContactKind::None) {
      schedulePair(ball, other, next, crossing, kind);
      return;
    }
    delay = contact.time;
  }
  schedulePair(ball, other, next, now_ + delay, kind);
}

/// A contact of `ball` and `other` at `time` (s) becomes the interaction of each for whom it
/// comes earlier: of `ball` through `next`, of `other` at once.
void EventDrivenWorld::schedulePair(std::uint32_t ball, std::uint32_t other, Event& next,
                                    double time, EventKind kind) {
  const BallMotion& partner = balls_[other];
  if (time < next.time && !asleep(ball)) next = {time, partner.version, other, kind};
  if (time < partner.interactionTime && !asleep(other))
    setInteraction(other, {time, balls_[ball].version, ball, kind});
}

void EventDrivenWorld::keepEarlier(Event& next, const Event& candidate) {
  if (candidate.time < next.time) next = candidate;
}

void EventDrivenWorld::setInteraction(std::uint32_t ball, const Event& interaction) {
  schedule_[ball].interaction = interaction;
  balls_[ball].interactionTime = interaction.time;
  reschedule(ball);
}

void EventDrivenWorld::reschedule(std::uint32_t ball) {
  calendar_.set(ball, schedule_[ball].earliest());
}

}  // namespace fooball::exact
