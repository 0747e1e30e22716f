#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

#include "fooball/random_balls.h"
#include "fooball/scene.h"

namespace fooball {

/// Lets GoogleTest print a Vec2 in failure messages as (x, y) instead of 16 raw bytes.
inline void PrintTo(Vec2 v, std::ostream* out) {
  *out << "(" << v.x << ", " << v.y << ")";
}

}  // namespace fooball

namespace fooball::testing {

/// A ball of density 1 kg/m² (mass π r²) unless a mass is given.
inline BallDef ball(Vec2 position, Vec2 velocity, double radius = 0.5, double mass = 0.0) {
  return {position, velocity, radius, mass > 0.0 ? mass : diskMass(radius), 0xffffff};
}

/// A 16 × 9 m box with all walls on, no gravity, no drag.
inline Scene emptyBox(double width = 16.0, double height = 9.0) {
  Scene scene;
  scene.name = "test";
  scene.box = {width, height};
  return scene;
}

/// `count` random balls (radius 0.1–0.2 m, speed 0.5–3 m/s) in a 16 × 9 m box.
inline constexpr double kDt = kDefaultDt;  ///< s, the default step
/// Relative: the error of a few dozen double operations.
inline constexpr double kRounding = 1e-12;

/// Three balls of different sizes, masses and colours, apart from each other and the walls.
inline Scene threeBalls() {
  Scene scene = emptyBox();
  scene.name = "three balls";
  scene.balls = {ball({3.0, 4.5}, {2.0, 1.0}, 0.5), ball({8.0, 2.0}, {-1.0, 0.5}, 0.3, 2.0),
                 ball({12.0, 6.0}, {0.0, -1.5}, 0.4)};
  scene.balls[0].color = 0xff0000;
  scene.balls[1].color = 0x00ff00;
  scene.balls[2].color = 0x0000ff;
  return scene;
}

inline Scene gas(std::size_t count, std::uint64_t seed = 7, double width = 16.0,
                 double height = 9.0) {
  Scene scene = emptyBox(width, height);
  RandomBalls spec;
  spec.count = count;
  spec.minRadius = 0.1;
  spec.maxRadius = 0.2;
  spec.seed = seed;
  addRandomBalls(scene, spec);
  return scene;
}

/// `bigCount` balls of radius 1 m, then `smallCount` of radius 0.04–0.06 m, all at 0.5–3 m/s,
/// in a `width` × `height` box: a few balls far too big for cells that fit the small ones.
inline Scene bigAmongSmall(std::size_t bigCount, std::size_t smallCount, double width,
                           double height, std::uint64_t seed = 11) {
  Scene scene = emptyBox(width, height);
  RandomBalls spec;
  spec.count = bigCount;
  spec.minRadius = spec.maxRadius = 1.0;
  spec.seed = seed;
  addRandomBalls(scene, spec);
  spec.count = smallCount;
  spec.minRadius = 0.04;
  spec.maxRadius = 0.06;
  addRandomBalls(scene, spec);
  return scene;
}

}  // namespace fooball::testing
