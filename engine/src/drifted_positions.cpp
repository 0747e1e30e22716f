#include "fooball/drifted_positions.h"

#include <algorithm>

namespace fooball {

void driftedPositions(const Simulation& run, double ahead, std::vector<Vec2>& out) {
  const auto positions = run.positions();
  out.assign(positions.begin(), positions.end());
  if (!(ahead > 0.0)) return;
  const auto velocities = run.velocities();
  const auto radii = run.radii();
  const Vec2 fall = 0.5 * ahead * ahead * run.world().gravity;
  const Walls& walls = run.world().walls;
  const Box& box = run.box();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Vec2 stepped = positions[i];
    const double r = radii[i];
    Vec2 p = stepped + ahead * velocities[i] + fall;
    // Contact positions, or the stepped one where the ball is already pressed in further.
    if (walls.left) p.x = std::max(p.x, std::min(stepped.x, r));
    if (walls.right) p.x = std::min(p.x, std::max(stepped.x, box.width - r));
    if (walls.bottom) p.y = std::max(p.y, std::min(stepped.y, r));
    if (walls.top) p.y = std::min(p.y, std::max(stepped.y, box.height - r));
    out[i] = p;
  }
}

}  // namespace fooball
