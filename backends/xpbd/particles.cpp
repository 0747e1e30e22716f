#include "particles.h"

#include <stdexcept>
#include <string>

#include "common/exact_size.h"

namespace fooball::xpbd {

void Particles::assign(std::span<const BallDef> balls) {
  const std::size_t count = balls.size();
  common::resizeExactly(particle, count);
  common::resizeExactly(id, count);
  common::resizeExactly(touches, count);
  common::resizeExactly(moved, count);
  for (std::size_t i = 0; i < count; ++i) {
    set(i, balls[i]);
    id[i] = static_cast<std::uint32_t>(i);
  }
}

void Particles::set(std::size_t slot, const BallDef& ball) {
  particle[slot] = {ball.position.x, ball.position.y, ball.velocity.x, ball.velocity.y,
                    ball.radius,     ball.mass,       ball.position.x, ball.position.y};
  touches[slot] = 0;
  moved[slot] = 0;
}

std::size_t Particles::slotOf(std::size_t sceneIndex) const {
  // Linear: only edits from the inspector ask, and a slot index would cost 4 bytes per ball.
  for (std::size_t slot = 0; slot < id.size(); ++slot) {
    if (id[slot] == sceneIndex) return slot;
  }
  throw std::out_of_range("no ball with scene index " + std::to_string(sceneIndex));
}

void Particles::permute(std::span<std::uint32_t> order) {
  // Slot k takes the ball from order[k]; that slot takes the ball from order[order[k]], and so
  // on until the cycle returns to its start. order[k] = k marks a slot as done.
  for (std::uint32_t start = 0; start < order.size(); ++start) {
    if (order[start] == start) continue;
    const Particle firstParticle = particle[start];
    const std::uint32_t firstId = id[start];
    const common::WallTouches firstTouches = touches[start];
    const std::uint8_t firstMoved = moved[start];
    std::uint32_t slot = start;
    for (;;) {
      const std::uint32_t source = order[slot];
      order[slot] = slot;
      if (source == start) {
        particle[slot] = firstParticle;
        id[slot] = firstId;
        touches[slot] = firstTouches;
        moved[slot] = firstMoved;
        break;
      }
      particle[slot] = particle[source];
      id[slot] = id[source];
      touches[slot] = touches[source];
      moved[slot] = moved[source];
      slot = source;
    }
  }
}

std::size_t Particles::memoryBytes() const {
  return particle.capacity() * sizeof(Particle) + id.capacity() * sizeof(std::uint32_t) +
         touches.capacity() * sizeof(common::WallTouches) + moved.capacity();
}

}  // namespace fooball::xpbd
