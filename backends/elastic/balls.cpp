#include "balls.h"

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

#include "common/exact_size.h"

namespace fooball::elastic {

namespace {

/// Whether no slot takes its ball from `distance` or more slots before it.
bool movesBackLessThan(std::span<const std::uint32_t> order, std::size_t distance) {
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (order[k] + distance <= k) return false;
  }
  return distance > 0;
}

}  // namespace

void Balls::assign(std::span<const BallDef> balls) {
  const std::size_t count = balls.size();
  common::resizeExactly(ball, count);
  common::resizeExactly(id, count);
  common::resizeExactly(touches, count);
  for (std::size_t i = 0; i < count; ++i) {
    const BallDef& def = balls[i];
    ball[i] = {def.position.x, def.position.y, def.velocity.x,
               def.velocity.y, def.radius,     def.mass};
    id[i] = static_cast<std::uint32_t>(i);
    touches[i] = 0;
  }
}

std::size_t Balls::slotOf(std::size_t sceneIndex) const {
  // Linear: only edits from the inspector ask, and a slot index would cost 4 bytes per ball.
  for (std::size_t slot = 0; slot < id.size(); ++slot) {
    if (id[slot] == sceneIndex) return slot;
  }
  throw std::out_of_range("no ball with scene index " + std::to_string(sceneIndex));
}

void Balls::permute(std::span<std::uint32_t> order, std::span<std::uint32_t> scratch) {
  // What a slot holds, kept in the ring until a later slot takes it.
  struct Held {
    Ball ball;
    std::uint32_t id;
    common::WallTouches touches;
  };
  const std::size_t ringSize = scratch.size_bytes() / sizeof(Held);
  if (!movesBackLessThan(order, ringSize)) {
    permuteByCycles(order);
    return;
  }
  auto* ring = reinterpret_cast<std::byte*>(scratch.data());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t source = order[k];
    Held next;
    if (source >= k) {
      next = {ball[source], id[source], touches[source]};  // not overwritten yet
    } else {
      std::memcpy(&next, ring + source % ringSize * sizeof(Held), sizeof(Held));
    }
    const Held leaving{ball[k], id[k], touches[k]};
    std::memcpy(ring + k % ringSize * sizeof(Held), &leaving, sizeof(Held));
    ball[k] = next.ball;
    id[k] = next.id;
    touches[k] = next.touches;
    order[k] = static_cast<std::uint32_t>(k);
  }
}

void Balls::permuteByCycles(std::span<std::uint32_t> order) {
  // Slot k takes the ball from order[k]; that slot takes the ball from order[order[k]], and so
  // on until the cycle returns to k. order[k] = k marks a slot as done.
  for (std::uint32_t start = 0; start < order.size(); ++start) {
    if (order[start] == start) continue;
    const Ball firstBall = ball[start];
    const std::uint32_t firstId = id[start];
    const common::WallTouches firstTouches = touches[start];
    std::uint32_t slot = start;
    for (;;) {
      const std::uint32_t source = order[slot];
      order[slot] = slot;
      if (source == start) {
        ball[slot] = firstBall;
        id[slot] = firstId;
        touches[slot] = firstTouches;
        break;
      }
      ball[slot] = ball[source];
      id[slot] = id[source];
      touches[slot] = touches[source];
      slot = source;
    }
  }
}

std::size_t Balls::memoryBytes() const {
  return ball.capacity() * sizeof(Ball) + id.capacity() * sizeof(std::uint32_t) +
         touches.capacity() * sizeof(common::WallTouches);
}

}  // namespace fooball::elastic
