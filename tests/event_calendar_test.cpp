// The exact backend's event queue against a plain array searched from end to end: whatever is
// set, shifted or laid out, the calendar's earliest is the array's minimum.
#include "exact/event_calendar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace fooball::exact {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The calendar and the times it should hold, side by side.
class CheckedCalendar {
 public:
  explicit CheckedCalendar(std::size_t ballCount) : times_(ballCount, kInfinity) {
    calendar_.reset(ballCount);
  }

  void set(std::uint32_t ball, double time) {
    calendar_.set(ball, time);
    times_[ball] = time;
  }
  void shiftOrigin(double offset) {
    calendar_.shiftOrigin(offset);
    for (double& time : times_)
      time -= offset;
  }
  void layOut() { calendar_.layOut(); }

  /// The calendar's earliest has the smallest time held (NaN counts as +∞), and is that ball's.
  void expectEarliestIsMinimum() {
    double minimum = kInfinity;
    for (const double time : times_) {
      if (time < minimum) minimum = time;
    }
    const EventHeap::Entry earliest = calendar_.earliest();
    if (minimum == kInfinity) {
      EXPECT_FALSE(earliest.time < kInfinity);
    } else {
      EXPECT_EQ(earliest.time, minimum);
    }
    ASSERT_LT(earliest.ball, times_.size());
    if (!std::isnan(earliest.time)) {
      EXPECT_EQ(times_[earliest.ball], earliest.time);
    }
  }

  /// Takes the earliest ball out of the way (as handling its event does) by giving it `later`.
  std::uint32_t popTo(double later) {
    const std::uint32_t ball = calendar_.earliest().ball;
    set(ball, later);
    return ball;
  }

 private:
  EventCalendar calendar_;
  std::vector<double> times_;
};

TEST(EventCalendar, EarliestIsTheMinimumThroughAnEventLoopWithShifts) {
  // An event loop as the world runs it: the earliest ball is handled and rescheduled an
  // exponential delay later, a few others are rescheduled earlier or later (its partners),
  // and the origin moves at the end of each step. Every pop is checked against the array.
  constexpr std::size_t kBalls = 500;
  std::mt19937_64 random(11);
  std::exponential_distribution<double> delay(1.0);
  std::uniform_int_distribution<std::uint32_t> anyBall(0, kBalls - 1);
  CheckedCalendar calendar(kBalls);
  for (std::uint32_t ball = 0; ball < kBalls; ++ball)
    calendar.set(ball, delay(random));
  calendar.layOut();
  double now = 0.0;
  for (int step = 0; step < 40; ++step) {
    const double dt = 0.05;
    for (int event = 0; event < 200; ++event) {
      calendar.expectEarliestIsMinimum();
      calendar.popTo(now + delay(random));
      calendar.set(anyBall(random), now + 0.01 * delay(random));  // a partner, soon
      calendar.set(anyBall(random), now + 20.0 * delay(random));  // one far beyond the year
      now += 0.0002;
    }
    calendar.shiftOrigin(dt);
    now -= dt;
  }
}

TEST(EventCalendar, InfinityAndNanNeverComeBeforeAFiniteTime) {
  CheckedCalendar calendar(8);
  calendar.expectEarliestIsMinimum();  // all +∞
  calendar.set(3, std::numeric_limits<double>::quiet_NaN());
  calendar.set(5, 2.0);
  calendar.layOut();
  calendar.expectEarliestIsMinimum();
  calendar.set(5, kInfinity);
  calendar.set(6, -kInfinity);
  calendar.expectEarliestIsMinimum();
  calendar.set(6, kInfinity);
  calendar.expectEarliestIsMinimum();  // only +∞ and NaN left
}

TEST(EventCalendar, EqualTimesAndTimesOnBucketEdgesComeOutInOrder) {
  // Times on a coarse grid: many balls share a time, and many sit exactly on bucket edges,
  // where a shift's rounding may carry them across.
  constexpr std::size_t kBalls = 300;
  std::mt19937_64 random(5);
  std::uniform_int_distribution<int> tick(0, 40);
  CheckedCalendar calendar(kBalls);
  for (std::uint32_t ball = 0; ball < kBalls; ++ball)
    calendar.set(ball, 0.1 * tick(random));
  calendar.layOut();
  for (int round = 0; round < 2000; ++round) {
    calendar.expectEarliestIsMinimum();
    calendar.popTo(0.1 * (40 + tick(random)));
    if (round % 100 == 99) calendar.shiftOrigin(0.3);
  }
}

TEST(EventCalendar, AFarOutlierDoesNotStallTheYear) {
  // One ball a million seconds out and the rest within a second: each year is laid out from what
  // is left, so the outlier comes out last and in order.
  CheckedCalendar calendar(100);
  calendar.set(0, 1e6);
  for (std::uint32_t ball = 1; ball < 100; ++ball)
    calendar.set(ball, 0.01 * ball);
  calendar.layOut();
  for (int round = 0; round < 99; ++round) {
    calendar.expectEarliestIsMinimum();
    calendar.popTo(kInfinity);
  }
  calendar.expectEarliestIsMinimum();
  EXPECT_EQ(calendar.popTo(kInfinity), 0u);
}

}  // namespace
}  // namespace fooball::exact
