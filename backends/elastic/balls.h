#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/wall_touches.h"
#include "fooball/scene.h"

namespace fooball::elastic {

/// One ball as the solver holds it, in one 48-byte record. Records rather than an array per
/// field: a pair test reads a neighbour's centre and radius, and a collision then its velocity
/// and mass, which is one or two cache lines per ball here and six in separate arrays — the
/// difference between streaming and waiting on memory once the balls outgrow the caches.
struct Ball {
  double x, y;    ///< m, centre
  double vx, vy;  ///< m/s
  double radius;  ///< m
  double mass;    ///< kg
};

/// The balls in slots, reordered by cell now and then for locality. `id[slot]` is the scene
/// index of the ball in `ball[slot]`, `touches[slot]` the walls it touches. 53 bytes per ball, the
/// bulk of the backend's memory.
struct Balls {
  std::vector<Ball> ball;
  std::vector<std::uint32_t> id;
  std::vector<common::WallTouches> touches;

  std::size_t size() const { return id.size(); }
  void assign(std::span<const BallDef> balls);
  std::size_t slotOf(std::size_t sceneIndex) const;

  /// Moves the ball in slot order[k] to slot k, without a second copy of the balls; `scratch`
  /// is borrowed memory (any size, contents lost). `order` must be a permutation; it is left as
  /// the identity (the order of the moved balls).
  ///
  /// Slots are filled in ascending order, and each ball a slot held is kept in a ring in
  /// `scratch` until a later slot takes it: a sequential pass, when no ball moves back by more
  /// than the ring holds — after a few substeps of drift, balls move back by a few grid rows.
  /// Otherwise the cycles of the permutation are followed one by one, which jumps around
  /// memory and costs several times more.
  void permute(std::span<std::uint32_t> order, std::span<std::uint32_t> scratch);

  /// Bytes the arrays hold (their capacities).
  std::size_t memoryBytes() const;

 private:
  void permuteByCycles(std::span<std::uint32_t> order);
};

}  // namespace fooball::elastic
