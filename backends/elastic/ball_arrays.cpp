#include "ball_arrays.h"

#include <stdexcept>

namespace fooball::elastic {

void BallArrays::assign(std::span<const BallDef> balls) {
  const std::size_t count = balls.size();
  for (auto* array : {&x, &y, &vx, &vy, &radius, &mass})
    array->resize(count);
  id.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    x[i] = balls[i].position.x;
    y[i] = balls[i].position.y;
    vx[i] = balls[i].velocity.x;
    vy[i] = balls[i].velocity.y;
    radius[i] = balls[i].radius;
    mass[i] = balls[i].mass;
    id[i] = static_cast<std::uint32_t>(i);
  }
}

std::size_t BallArrays::slotOf(std::size_t sceneIndex) const {
  // Linear: only edits from the inspector ask, and a slot index would cost 4 bytes per ball.
  for (std::size_t slot = 0; slot < id.size(); ++slot) {
    if (id[slot] == sceneIndex) return slot;
  }
  throw std::out_of_range("no ball with scene index " + std::to_string(sceneIndex));
}

void BallArrays::permute(std::span<const std::uint32_t> order, std::vector<double>& scratch,
                         std::vector<std::uint32_t>& idScratch) {
  scratch.resize(order.size());
  for (auto* array : {&x, &y, &vx, &vy, &radius, &mass}) {
    for (std::size_t k = 0; k < order.size(); ++k)
      scratch[k] = (*array)[order[k]];
    array->swap(scratch);
  }
  idScratch.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    idScratch[k] = id[order[k]];
  id.swap(idScratch);
}

}  // namespace fooball::elastic
