#include "wall_contacts.h"

#include <cmath>

namespace fooball::xpbd {

namespace {

/// The contact of `slot` with `wall` in this substep, pushed `depth` (m) back in: recorded the
/// first time (one record per axis and ball, its index in recordOf), accumulated after. Returns
/// 1 when it begins an event.
std::uint64_t touch(Particles& particles, std::uint32_t slot, Wall wall, double before,
                    double depth, std::vector<WallContact>& contacts,
                    std::vector<std::uint32_t>& recordOf) {
  particles.moved[slot] = 1;
  const std::uint32_t axisRecord = 2 * slot + (wall <= Wall::Right ? 0 : 1);
  // A record of this substep's: the record at recordOf names this ball and wall (an index left
  // from an earlier substep names another, or lies beyond the records).
  const std::uint32_t record = recordOf[axisRecord];
  if (record < contacts.size() && contacts[record].slot == slot && contacts[record].wall == wall) {
    contacts[record].pushed += depth;
    return 0;
  }
  recordOf[axisRecord] = static_cast<std::uint32_t>(contacts.size());
  contacts.push_back({slot, wall, before, depth, 0.0});
  const auto bit = static_cast<common::WallBit>(1u << static_cast<unsigned>(wall));
  return common::touchWall(particles.touches[slot], bit);
}

}  // namespace

void WallContacts::release(Particles& particles) const {
  for (std::size_t slot = 0; slot < particles.size(); ++slot) {
    common::WallTouches& touches = particles.touches[slot];
    if (touches == 0) continue;
    const Particle& p = particles.particle[slot];
    touches = common::stillTouching(touches, {p.x, p.y}, p.radius, box_);
  }
}

std::uint64_t WallContacts::project(Particles& particles, std::vector<WallContact>& contacts,
                                    std::vector<std::uint32_t>& recordOf) const {
  if (!anyOn()) return 0;
  std::uint64_t events = 0;
  const double width = box_.width;
  const double height = box_.height;
  for (std::uint32_t slot = 0; slot < particles.size(); ++slot) {
    Particle& p = particles.particle[slot];
    const double r = p.radius;
    // Most balls touch no wall: two comparisons per axis. Written so that NaN counts as outside
    // and is put back.
    if (!(p.x >= r && p.x <= width - r)) {
      if (walls_.left && walls_.right && width < 2.0 * r) {
        p.x = 0.5 * width;  // wider than the box: between both walls
      } else if (walls_.left && !(p.x >= r)) {
        const double depth = std::isnan(p.x) ? 0.0 : r - p.x;
        p.x = r;
        events += touch(particles, slot, Wall::Left, -p.vx, depth, contacts, recordOf);
      } else if (walls_.right && !(p.x <= width - r)) {
        const double depth = std::isnan(p.x) ? 0.0 : p.x - (width - r);
        p.x = width - r;
        events += touch(particles, slot, Wall::Right, p.vx, depth, contacts, recordOf);
      }
    }
    if (!(p.y >= r && p.y <= height - r)) {
      if (walls_.bottom && walls_.top && height < 2.0 * r) {
        p.y = 0.5 * height;
      } else if (walls_.bottom && !(p.y >= r)) {
        const double depth = std::isnan(p.y) ? 0.0 : r - p.y;
        p.y = r;
        events += touch(particles, slot, Wall::Bottom, -p.vy, depth, contacts, recordOf);
      } else if (walls_.top && !(p.y <= height - r)) {
        const double depth = std::isnan(p.y) ? 0.0 : p.y - (height - r);
        p.y = height - r;
        events += touch(particles, slot, Wall::Top, p.vy, depth, contacts, recordOf);
      }
    }
  }
  return events;
}

void restituteWalls(Particles& particles, std::vector<WallContact>& contacts) {
  for (WallContact& contact : contacts) {
    Particle& p = particles.particle[contact.slot];
    // The outward normal: −x, +x, −y, +y.
    const bool high = contact.wall == Wall::Right || contact.wall == Wall::Top;
    double& v = contact.wall <= Wall::Right ? p.vx : p.vy;
    const double into = high ? v : -v;  // m/s, v_n
    const double change = std::min(-contact.before, 0.0) - into;
    v += high ? change : -change;
    contact.change += change;
  }
}

double wallImpulse(const Particles& particles, const std::vector<WallContact>& contacts, double h) {
  double impulse = 0.0;
  for (const WallContact& contact : contacts) {
    impulse +=
        particles.particle[contact.slot].mass * std::abs(contact.change - contact.pushed / h);
  }
  return impulse;
}

}  // namespace fooball::xpbd
