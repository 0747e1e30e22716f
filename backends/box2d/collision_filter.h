#pragma once

#include <box2d/b2_fixture.h>

namespace fooball::box2d_detail {

/// Category bits: walls and balls. Balls always collide with walls; with each other only while
/// WorldSettings::ballCollisions is on, which the mask turns off without touching the bodies.
inline constexpr uint16 kWallCategory = 0x0001;
inline constexpr uint16 kBallCategory = 0x0002;

inline b2Filter wallFilter() {
  b2Filter filter;
  filter.categoryBits = kWallCategory;
  filter.maskBits = kBallCategory;
  return filter;
}

inline b2Filter ballFilter(bool ballCollisions) {
  b2Filter filter;
  filter.categoryBits = kBallCategory;
  filter.maskBits = ballCollisions ? uint16{kWallCategory | kBallCategory} : kWallCategory;
  return filter;
}

}  // namespace fooball::box2d_detail
