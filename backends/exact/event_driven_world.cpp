#include "event_driven_world.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fooball::exact {

namespace {

/// Legitimate chains of simultaneous events (a Newton's cradle passes the momentum through one
/// ball per event) are at most a few per ball; a longer run at one instant is a zero-time loop.
constexpr std::uint64_t kSimultaneousEventsPerBall = 16;
constexpr std::uint64_t kSimultaneousEventsFloor = 1024;
/// The event cap counts as for at least this many balls, so tiny scenes are not cut short.
constexpr std::size_t kEventCapFloorBalls = 500;
/// With more kicked balls than 1 in this many, predicting everything again is cheaper.
constexpr std::size_t kKickedFractionForRebuild = 8;

}  // namespace

void EventDrivenWorld::load(const Scene& scene) {
  box_ = scene.box;
  world_ = scene.world;
  updateRestScales();
  const std::size_t count = scene.balls.size();
  balls_.assign(count, BallMotion{});
  mass_.resize(count);
  for (std::size_t ball = 0; ball < count; ++ball) {
    const BallDef& def = scene.balls[ball];
    balls_[ball].position = def.position;
    balls_[ball].velocity = def.velocity;
    balls_[ball].radius = def.radius;
    mass_[ball] = def.mass;
  }
  restingOn_.assign(count, 0);
  touches_.assign(count, 0);
  restingCount_ = 0;
  woken_.clear();
  woken_.reserve(count);
  forced_.clear();
  forced_.reserve(count);
  counters_ = {};
  statistics_ = {};
  calendarValid_ = false;
  now_ = 0.0;
}

void EventDrivenWorld::setLimits(const EventLimits& limits) {
  if (limits.ballRestTime != limits_.ballRestTime)
    calendarValid_ = false;  // wakes every ball: they sleep again by the new rule
  limits_ = limits;
  updateRestScales();
}

void EventDrivenWorld::setWorld(const WorldSettings& world) {
  world_ = world;
  updateRestScales();
  calendarValid_ = false;
}

void EventDrivenWorld::setBall(std::size_t index, const BallDef& ball) {
  balls_[index].position = ball.position;
  balls_[index].velocity = ball.velocity;
  balls_[index].radius = ball.radius;
  mass_[index] = ball.mass;
  touches_[index] = 0;  // an edited ball begins its contacts anew
  calendarValid_ = false;
}

void EventDrivenWorld::step(double dt, std::span<const Vec2> forces) {
  statistics_.eventsThisStep = 0;
  statistics_.collisionsThisStep = 0;
  if (ballCount() == 0) return;
  applyForces(dt, forces);
  if (!calendarValid_) rebuild();
  const bool completed = runEvents(dt);
  for (std::uint32_t ball = 0; ball < ballCount(); ++ball) {
    advance(ball, dt);
    releaseWalls(ball);
  }
  if (!completed) {
    ++statistics_.cutShortSteps;
    confineToWalls();
    calendarValid_ = false;
  }
  moveOriginTo(dt);
}

void EventDrivenWorld::applyForces(double dt, std::span<const Vec2> forces) {
  forced_.clear();
  const std::size_t count = std::min(forces.size(), ballCount());
  for (std::uint32_t ball = 0; ball < count; ++ball) {
    if (forces[ball] == Vec2{}) continue;
    balls_[ball].velocity += (dt / mass_[ball]) * forces[ball];
    ++balls_[ball].version;
    liftIfMoving(ball);
    forced_.push_back(ball);
  }
  if (!calendarValid_ || forced_.empty()) return;
  if (forced_.size() * kKickedFractionForRebuild > ballCount()) {
    calendarValid_ = false;
    return;
  }
  for (std::uint32_t ball : forced_)
    predict(ball);
  predictWoken();
}

void EventDrivenWorld::rebuild() {
  now_ = 0.0;
  const std::uint32_t count = static_cast<std::uint32_t>(ballCount());
  double largestRadius = 0.0;
  for (BallMotion& ball : balls_) {
    ++ball.version;
    ball.interactionTime = std::numeric_limits<double>::infinity();
    largestRadius = std::max(largestRadius, ball.radius);
  }
  cellsActive_ = world_.ballCollisions && count > 1;
  if (cellsActive_) {
    cells_.configure(box_.width, box_.height, 2.0 * largestRadius, count);
    for (std::uint32_t ball = 0; ball < count; ++ball)
      cells_.insert(ball, balls_[ball].position);
  }
  schedule_.assign(count, BallSchedule{});
  restingOn_.assign(count, 0);  // every ball wakes; the rest rules lay it down again
  restingCount_ = 0;
  woken_.clear();
  calendar_.reset(count);
  for (std::uint32_t ball = 0; ball < count; ++ball)
    predict(ball);
  calendar_.layOut();
  calendarValid_ = true;
}

bool EventDrivenWorld::runEvents(double dt) {
  const double eventCap = limits_.maxEventsPerBall == EventLimits::kNoEventCap
                              ? std::numeric_limits<double>::infinity()
                              : limits_.maxEventsPerBall *
                                    static_cast<double>(std::max(ballCount(), kEventCapFloorBalls));
  const std::uint64_t simultaneousCap =
      kSimultaneousEventsPerBall * ballCount() + kSimultaneousEventsFloor;
  std::uint64_t simultaneous = 0;
  double previousTime = -std::numeric_limits<double>::infinity();
  while (true) {
    const auto [time, ball] = calendar_.earliest();
    if (!(time <= dt)) return true;
    if (static_cast<double>(statistics_.eventsThisStep) >= eventCap) return false;
    if (time == previousTime) {
      if (++simultaneous > simultaneousCap) return false;
    } else {
      simultaneous = 0;
      previousTime = time;
    }
    now_ = time;
    ++statistics_.eventsThisStep;
    ++statistics_.events;
    const BallSchedule& schedule = schedule_[ball];
    if (schedule.crossing.time < schedule.interaction.time) {
      crossCell(ball, schedule.crossing.face);
    } else {
      handle(ball, schedule.interaction);
    }
  }
}

/// After a cut-short step the balls flew to dt without events, so some passed through walls.
/// Each is put back on the wall it crossed, moving inwards with the normal speed it had when it
/// crossed: in free flight along the normal, v² − 2·g_n·x is constant, so
///   v_n'² = v_n² + 2·g_n·(contact − x)
/// keeps the energy exactly (moving the centre by contact − x changes the potential energy by
/// −m·g_n·(contact − x)). Merely clamping the position would keep v_n and gain m·|g_n|·depth
/// for a ball that fell through the floor. A negative v_n'² (only possible with drag, which
/// slowed it after the crossing) leaves it at rest there, losing energy, never gaining it.
void EventDrivenWorld::confineToWalls() {
  for (std::uint32_t ball = 0; ball < ballCount(); ++ball) {
    for (int side = 0; side < 4; ++side) {
      const Side wall = static_cast<Side>(side);
      if (!wallOn(wall)) continue;
      const int axis = axisOf(wall);
      const double inward = isLowerSide(wall) ? 1.0 : -1.0;
      const double contact = contactCoordinate(wall, balls_[ball].radius);
      double& coordinate = componentRef(balls_[ball].position, axis);
      double& normalVelocity = componentRef(balls_[ball].velocity, axis);
      const double depth = inward * (contact - coordinate);  // m beyond the contact position
      if (depth < 0.0 || (depth == 0.0 && inward * normalVelocity >= 0.0)) continue;
      const double squared = normalVelocity * normalVelocity +
                             2.0 * component(world_.gravity, axis) * (contact - coordinate);
      const double newVelocity = inward * std::sqrt(std::max(squared, 0.0));
      counters_.wallImpulse += mass_[ball] * inward * (newVelocity - normalVelocity);
      counters_.wallCollisions += touchWall(ball, wall);
      coordinate = contact;
      normalVelocity = newVelocity;
    }
  }
}

void EventDrivenWorld::moveOriginTo(double dt) {
  for (BallMotion& ball : balls_) {
    ball.time = 0.0;
    ball.interactionTime -= dt;
  }
  if (calendarValid_) {
    for (BallSchedule& schedule : schedule_) {
      schedule.interaction.time -= dt;
      schedule.crossing.time -= dt;
    }
    calendar_.shiftOrigin(dt);
  }
  now_ = 0.0;
}

bool EventDrivenWorld::wallOn(Side side) const {
  switch (side) {
    case Side::Left:
      return world_.walls.left;
    case Side::Right:
      return world_.walls.right;
    case Side::Bottom:
      return world_.walls.bottom;
    case Side::Top:
      return world_.walls.top;
  }
  return false;
}

double EventDrivenWorld::contactCoordinate(Side wall, double radius) const {
  switch (wall) {
    case Side::Left:
    case Side::Bottom:
      return radius;
    case Side::Right:
      return box_.width - radius;
    case Side::Top:
      return box_.height - radius;
  }
  return radius;
}

}  // namespace fooball::exact
