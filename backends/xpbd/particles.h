#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::xpbd {

/// One ball as the solver holds it: one 64-byte record, a cache line. Records rather than an
/// array per field: a contact reads both balls' centres, radii and masses, and the velocity pass
/// their velocities, which is one line per ball here and up to eight in separate arrays.
struct Particle {
  double x, y;          ///< m, centre
  double vx, vy;        ///< m/s
  double radius;        ///< m
  double mass;          ///< kg
  double xPrev, yPrev;  ///< m, centre at the start of the substep, for v = (x − x_prev)/h
};

/// The balls in slots, reordered by grid cell now and then for locality. Per slot: the record,
/// the scene index, the walls it touches (common/wall_touches.h) and whether a constraint moved
/// the ball in this substep. 70 bytes per ball.
struct Particles {
  std::vector<Particle> particle;
  std::vector<std::uint32_t> id;             ///< scene index of the ball in each slot
  std::vector<common::WallTouches> touches;  ///< the walls each ball touches
  std::vector<std::uint8_t> moved;           ///< 1: a constraint moved the ball in this substep

  std::size_t size() const { return id.size(); }
  void assign(std::span<const BallDef> balls);
  void set(std::size_t slot, const BallDef& ball);
  std::size_t slotOf(std::size_t sceneIndex) const;

  /// Moves the ball in slot order[k] to slot k, following the permutation's cycles (no second
  /// copy of the balls). `order` must be a permutation; it is left as the identity.
  void permute(std::span<std::uint32_t> order);

  std::size_t memoryBytes() const;
};

}  // namespace fooball::xpbd
