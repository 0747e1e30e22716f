#include "wall_contacts.h"

#include <cmath>

#include "contact_memory.h"

namespace fooball::xpbd {

namespace {

/// Bits 1 … kContactMemory of a wall's history byte: active in one of the substeps before.
constexpr std::uint32_t kRecentBits = ((1u << kContactMemory) - 1u) << 1;
static_assert(kContactMemory <= 7, "a wall's history is one byte");

std::uint32_t wallShift(Wall wall) {
  return 8u * static_cast<std::uint32_t>(wall);
}

/// The contact of `slot` with `wall` in this substep, pushed `depth` (m) back in: recorded the
/// first time (one record per axis and ball, its index in recordOf), accumulated after. Returns
/// 1 when it begins an event.
std::uint64_t touch(Particles& particles, std::uint32_t slot, Wall wall, double before,
                    double depth, std::vector<WallContact>& contacts,
                    std::vector<std::uint32_t>& recordOf) {
  particles.moved[slot] = 1;
  std::uint32_t& history = particles.wallHistory[slot];
  const std::uint32_t shift = wallShift(wall);
  const std::uint32_t axisRecord = 2 * slot + (wall <= Wall::Right ? 0 : 1);
  if ((history >> shift) & 1u) {
    contacts[recordOf[axisRecord]].pushed += depth;
    return 0;
  }
  history |= 1u << shift;
  recordOf[axisRecord] = static_cast<std::uint32_t>(contacts.size());
  contacts.push_back({slot, wall, before, depth, 0.0});
  return ((history >> shift) & kRecentBits) == 0 ? 1 : 0;
}

}  // namespace

void WallContacts::age(Particles& particles) {
  // Each byte shifted by one, the bit leaving a byte dropped.
  for (std::uint32_t& history : particles.wallHistory)
    history = (history << 1) & 0xfefefefeu;
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
