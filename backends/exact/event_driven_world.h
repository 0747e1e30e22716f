#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "axis.h"
#include "ball_motion.h"
#include "common/wall_touches.h"
#include "event.h"
#include "event_calendar.h"
#include "event_cells.h"
#include "fooball/backend.h"
#include "fooball/scene.h"

namespace fooball::exact {

/// Guards against event explosions; both are backend options (exact_options.cpp).
struct EventLimits {
  /// s. A wall bounce under gravity whose flight back would last less than this leaves the ball
  /// resting on the wall: its normal speed (at most g·t/2) is dropped and the wall carries
  /// gravity's normal component from then on. Without it a ball lying on the floor within
  /// rounding bounces at an unbounded rate.
  double restBounceTime = 1e-6;
  /// s. Balls resting on balls (ball_rest.cpp): a ball slower than |g|·t that walls and sleeping
  /// balls hold against gravity falls asleep, and a pair feeling different gravity (one asleep
  /// or on a wall) leaves a contact at |Δg|·t/2 at least, so its next contact is about t away.
  /// 0: balls never sleep and contacts stay elastic.
  double ballRestTime = kDefaultBallRestTime;
  static constexpr double kDefaultBallRestTime = 1e-2;
  /// Average events per ball in one step (counted as for at least 500 balls) before the step is
  /// cut short and the rest of it moves without collisions; kNoEventCap (the default) never
  /// cuts a step short, so every step is exact. A cap bounds the work of a step that holds very
  /// many events (a pile on a pile under gravity, a huge mass ratio) at the price of the physics.
  double maxEventsPerBall = kNoEventCap;
  static constexpr double kNoEventCap = 0.0;
};

/// What the solver did, beside the backend counters.
struct EventStatistics {
  std::uint64_t events = 0;  ///< events handled since load (collisions, bounces, cell crossings)
  std::uint64_t eventsThisStep = 0;
  std::uint64_t collisionsThisStep = 0;
  std::uint64_t cutShortSteps = 0;  ///< steps that hit the event cap or a zero-time loop
  /// J, energy changed by the rest rules: laying balls to rest on walls, putting them to sleep
  /// and the least speed a pressed pair leaves a contact with (ball_rest.cpp).
  double restEnergyChange = 0.0;
  /// J, what restEnergyChange may reach in size: Σ ½m(g_n·t/2)² per wall rest (t:
  /// restBounceTime), m(|g|·t)² per sleep and ½μ(|Δg|·t/2)² per pressed contact (t:
  /// ballRestTime; μ the pair's reduced mass, m alone against a sleeping ball).
  double restEnergyBound = 0.0;
  std::uint64_t sleeps = 0;  ///< balls fallen asleep since load
  std::uint64_t wakes = 0;   ///< sleeping balls woken by a hit, a force or a lost support
};

/// Event-driven hard-disk dynamics with exact free flight (free_flight.h).
///
/// Each ball keeps its state at its own last-update time and is advanced only when an event
/// involves it; each has one entry in the calendar, the earlier of its next interaction and its
/// next cell crossing; cells bound the partners a ball must be checked against and the calendar
/// is a calendar queue, so an event costs O(1) whatever N. Time inside a step runs from 0 (the
/// step's start) to dt; at the end every ball is brought to dt and the origin moves there, so
/// the state read between steps is exact and times stay small.
class EventDrivenWorld {
 public:
  void setLimits(const EventLimits& limits);

  /// Takes the scene (already validated) and zeroes counters and statistics.
  void load(const Scene& scene);
  void setWorld(const WorldSettings& world);
  void setBall(std::size_t index, const BallDef& ball);

  /// Applies forces[i]·dt as impulses (N·s) now, then advances exactly dt seconds.
  void step(double dt, std::span<const Vec2> forces);

  std::size_t ballCount() const { return balls_.size(); }
  const Box& box() const { return box_; }
  const WorldSettings& world() const { return world_; }
  Vec2 position(std::size_t ball) const { return balls_[ball].position; }
  Vec2 velocity(std::size_t ball) const { return balls_[ball].velocity; }
  double radius(std::size_t ball) const { return balls_[ball].radius; }
  double mass(std::size_t ball) const { return mass_[ball]; }

  const BackendCounters& counters() const { return counters_; }
  const EventStatistics& statistics() const { return statistics_; }
  /// Balls resting now: on a wall or asleep.
  std::size_t restingBallCount() const { return restingCount_; }

 private:
  // event_driven_world.cpp: the step.
  void applyForces(double dt, std::span<const Vec2> forces);
  void rebuild();
  bool runEvents(double dt);
  void confineToWalls();
  void moveOriginTo(double dt);

  // event_prediction.cpp: each ball's next events.
  void predict(std::uint32_t ball);
  void crossCell(std::uint32_t ball, Side side);
  bool wallReachable(std::uint32_t ball, Side wall) const;
  Event wallContact(std::uint32_t ball, Side wall) const;
  CellCrossing nextCellCrossing(std::uint32_t ball) const;
  CellCrossing straightCellCrossing(std::uint32_t ball) const;
  CellCrossing curvedCellCrossing(std::uint32_t ball) const;
  void checkPair(std::uint32_t ball, std::uint32_t other, Event& next);
  void checkStraightPair(std::uint32_t ball, std::uint32_t other, Event& next);
  void checkCurvedPair(std::uint32_t ball, std::uint32_t other, Event& next);
  void schedulePair(std::uint32_t ball, std::uint32_t other, Event& next, double time,
                    EventKind kind);
  static void keepEarlier(Event& next, const Event& candidate);
  void setInteraction(std::uint32_t ball, const Event& interaction);
  void reschedule(std::uint32_t ball);

  // event_handling.cpp: what events do.
  void advance(std::uint32_t ball, double time);
  void handle(std::uint32_t ball, const Event& interaction);
  void collide(std::uint32_t first, std::uint32_t second);
  void bounce(std::uint32_t ball, Side wall);
  void layToRest(std::uint32_t ball, Side wall);
  void liftIfMoving(std::uint32_t ball);

  // ball_rest.cpp: balls resting on balls.
  bool asleep(std::uint32_t ball) const {
    return restingCount_ != 0 && (restingOn_[ball] & kAsleep) != 0;
  }
  bool sleepActive() const { return restSpeed_ > 0.0 && cellsActive_; }
  void updateRestScales();
  void setRestBits(std::uint32_t ball, std::uint8_t bits);
  double restKick(std::uint32_t first, std::uint32_t second) const;
  double wakeSpeed(std::uint32_t sleeper) const;
  void exchange(std::uint32_t first, std::uint32_t second);
  bool held(std::uint32_t ball) const;
  bool trySleep(std::uint32_t ball);
  void meetSleeper(std::uint32_t mover, std::uint32_t sleeper);
  void wake(std::uint32_t ball);
  void predictWoken();

  /// No gravity and no drag: every ball flies in a straight line at constant speed, and the
  /// predictions take their closed forms directly (nobody rests on a wall without gravity).
  bool straightFlight() const { return world_.airResistance == 0.0 && world_.gravity == Vec2{}; }
  /// m/s², the gravity the ball feels (less what walls it rests on carry).
  Vec2 gravityOf(std::uint32_t ball) const {
    if (restingCount_ == 0) return world_.gravity;
    return (restingOn_[ball] & kAsleep) != 0 ? Vec2{} : gravityOn(restingOn_[ball], world_.gravity);
  }
  bool restsAlong(std::uint32_t ball, int axis) const {
    return restingCount_ != 0 && (restingOn_[ball] & axisSideBits(axis)) != 0;
  }
  bool wallOn(Side side) const;
  /// Forgets the walls `ball` has left, seen where it is now: at each of its events and at the
  /// end of each step (many bounces can fit in one step).
  void releaseWalls(std::uint32_t ball) {
    if (touches_[ball] != 0) {
      touches_[ball] =
          common::stillTouching(touches_[ball], balls_[ball].position, balls_[ball].radius, box_);
    }
  }
  /// `wall` turned `ball` back: 1 when that begins a collision (common/wall_touches.h).
  std::uint64_t touchWall(std::uint32_t ball, Side wall) {
    return common::touchWall(touches_[ball], static_cast<common::WallBit>(sideBit(wall)));
  }
  /// m, the centre coordinate at which a ball of `radius` touches `wall`.
  double contactCoordinate(Side wall, double radius) const;

  Box box_;
  WorldSettings world_;
  EventLimits limits_;

  std::vector<BallMotion> balls_;       ///< in scene order
  std::vector<double> mass_;            ///< kg, per ball
  std::vector<BallSchedule> schedule_;  ///< per ball
  /// per ball, sideBit() of each wall it rests on, and kAsleep
  std::vector<std::uint8_t> restingOn_;
  /// Per ball, the walls it touches (common/wall_touches.h; sideBit() is its WallBit).
  std::vector<common::WallTouches> touches_;
  std::size_t restingCount_ = 0;  ///< balls resting on some wall or asleep
  double restSpeed_ = 0.0;   ///< m/s, |g|·ballRestTime/2, the least speed off a pressed contact
  double sleepSpeed_ = 0.0;  ///< m/s, |g|·ballRestTime, the most a ball falling asleep has
  double supportGap_ = 0.0;  ///< m, v_rest²/(2|g|): a gap to a support that still holds
  std::vector<std::uint32_t> woken_;   ///< balls woken by this event, to predict again
  std::vector<std::uint32_t> forced_;  ///< balls kicked by this step's forces

  EventCalendar calendar_;
  EventCells cells_;
  bool cellsActive_ = false;    ///< ball collisions on and at least two balls
  bool calendarValid_ = false;  ///< false after load, setWorld, setBall or a cut-short step
  double now_ = 0.0;            ///< s since the step began

  BackendCounters counters_;
  EventStatistics statistics_;
};

}  // namespace fooball::exact
