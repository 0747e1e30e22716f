#pragma once

#include <cstdint>
#include <limits>

#include "axis.h"

namespace fooball::exact {

enum class EventKind : std::uint8_t {
  None,     ///< nothing scheduled (time +∞)
  Pair,     ///< collision with ball `target`
  Wall,     ///< bounce on wall `target` (a Side)
  Recheck,  ///< predict again: a curved pair search stopped short here
};

/// A ball's earliest predicted interaction. A pair event is valid while its partner's version
/// still equals `partnerVersion`: any change of the partner's motion bumps that version (lazy
/// invalidation).
struct Event {
  double time = std::numeric_limits<double>::infinity();  ///< s, since the step began
  std::uint64_t partnerVersion = 0;
  std::uint32_t target = 0;
  EventKind kind = EventKind::None;
};

/// The moment a ball's centre leaves its cell, and through which face.
struct CellCrossing {
  double time = std::numeric_limits<double>::infinity();  ///< s, since the step began
  Side face = Side::Left;
};

/// Everything scheduled for one ball, kept together because the event loop reads both halves
/// at once; the calendar orders balls by the earlier.
struct BallSchedule {
  Event interaction;
  CellCrossing crossing;

  double earliest() const {
    return crossing.time < interaction.time ? crossing.time : interaction.time;
  }
};

}  // namespace fooball::exact
