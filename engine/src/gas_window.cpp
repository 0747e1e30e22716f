#include "fooball/gas_window.h"

#include <cmath>
#include <stdexcept>

namespace fooball {

GasWindow::GasWindow(double seconds) : seconds_(seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    throw std::invalid_argument("gas window: must span a positive time");
}

void GasWindow::add(double time, double wallImpulse, std::uint64_t ballCollisions) {
  if (!samples_.empty() &&
      (time < samples_.back().time || ballCollisions < samples_.back().ballCollisions ||
       wallImpulse < samples_.back().wallImpulse))
    samples_.clear();
  samples_.push_back({time, wallImpulse, ballCollisions});
  // Drop the oldest while the next one is old enough on its own: the oldest kept is then the
  // last at or before time − seconds_, and the span covers the whole window once there is one.
  while (samples_.size() > 2 && samples_[1].time <= time - seconds_)
    samples_.pop_front();
}

double GasWindow::span() const {
  return samples_.size() < 2 ? 0.0 : samples_.back().time - samples_.front().time;
}

double GasWindow::wallPressure(const Box& box, const Walls& walls) const {
  const double length = (walls.left ? box.height : 0.0) + (walls.right ? box.height : 0.0) +
                        (walls.bottom ? box.width : 0.0) + (walls.top ? box.width : 0.0);
  if (span() <= 0.0 || length <= 0.0) return 0.0;
  return (samples_.back().wallImpulse - samples_.front().wallImpulse) / (span() * length);
}

double GasWindow::collisionRate(std::size_t balls) const {
  if (span() <= 0.0 || balls == 0) return 0.0;
  const auto collisions =
      static_cast<double>(samples_.back().ballCollisions - samples_.front().ballCollisions);
  return 2.0 * collisions / (static_cast<double>(balls) * span());
}

}  // namespace fooball
