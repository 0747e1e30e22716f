#pragma once

#include <cstdint>

#include "fooball/vec2.h"

namespace fooball::exact {

/// A wall, or the matching face of a cell. Axis = side / 2 (0: x, 1: y); even sides are the
/// lower ones, whose allowed region lies at larger coordinates.
enum class Side : std::uint8_t { Left = 0, Right = 1, Bottom = 2, Top = 3 };

inline int axisOf(Side side) {
  return static_cast<int>(side) / 2;
}
inline bool isLowerSide(Side side) {
  return static_cast<int>(side) % 2 == 0;
}
inline Side lowerSide(int axis) {
  return axis == 0 ? Side::Left : Side::Bottom;
}
inline Side upperSide(int axis) {
  return axis == 0 ? Side::Right : Side::Top;
}

/// Bit masks over sides, for the walls a ball rests on.
inline std::uint8_t sideBit(Side side) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(side));
}
inline std::uint8_t axisSideBits(int axis) {
  return axis == 0 ? 0b0011 : 0b1100;
}

inline double component(Vec2 v, int axis) {
  return axis == 0 ? v.x : v.y;
}
inline double& componentRef(Vec2& v, int axis) {
  return axis == 0 ? v.x : v.y;
}

}  // namespace fooball::exact
