#include "pair_contacts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace fooball::xpbd {

namespace {

/// The unit normal from a to b for centres (dx, dy) = x_b − x_a apart at `distance` (m).
/// Coincident centres get a deterministic normal instead of a division by zero: along a's
/// velocity relative to b (so a is pushed back where it came from), else along x.
struct Normal {
  double x, y;
};

Normal normalOf(const Particle& a, const Particle& b, double dx, double dy, double distance) {
  if (distance > 0.0) return {dx / distance, dy / distance};
  const double wx = a.vx - b.vx;
  const double wy = a.vy - b.vy;
  const double speed = std::hypot(wx, wy);
  return speed > 0.0 ? Normal{wx / speed, wy / speed} : Normal{1.0, 0.0};
}

/// a's share of a correction between a and b: w_a/(w_a + w_b) = m_b/(m_a + m_b), written as
/// 1/(1 + m_a/m_b) so that mass ratios of 1e8 neither overflow nor lose the light ball's share.
double shareOf(const Particle& a, const Particle& b) {
  return 1.0 / (1.0 + a.mass / b.mass);
}

/// Whether a and b overlap (strictly). A NaN centre overlaps nothing, so it spreads no further.
bool overlap(const Particle& a, const Particle& b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double reach = a.radius + b.radius;
  return dx * dx + dy * dy < reach * reach;
}

}  // namespace

void PairContacts::meet(std::span<const Particle> particles, std::uint32_t a,
                        std::span<const std::uint32_t> candidates) {
  const Particle& pa = particles[a];
  for (const std::uint32_t b : candidates) {
    const Particle& pb = particles[b];
    if (overlap(pa, pb)) contacts_.push_back({a, b, pa.vx - pb.vx, pa.vy - pb.vy, 0});
  }
}

void PairContacts::find(std::span<const Particle> particles, const common::CellLists& grid) {
  contacts_.clear();
  const int columns = grid.columns();
  const int rows = grid.rows();
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const int cell = row * columns + column;
      const auto here = grid.slotsIn(cell, cell + 1);
      if (here.empty()) continue;
      // This cell and its right neighbour are one range of sorted slots, the three cells above
      // another.
      const auto hereAndRight = grid.slotsIn(cell, column + 1 < columns ? cell + 2 : cell + 1);
      const auto above = row + 1 < rows
                             ? grid.slotsIn(cell + columns - (column > 0 ? 1 : 0),
                                            cell + columns + (column + 1 < columns ? 2 : 1))
                             : grid.slotsIn(cell, cell);
      for (std::size_t k = 0; k < here.size(); ++k) {
        meet(particles, here[k], hereAndRight.subspan(k + 1));
        meet(particles, here[k], above);
      }
    }
  }
  findOversized(particles, grid);
}

void PairContacts::findOversized(std::span<const Particle> particles,
                                 const common::CellLists& grid) {
  const auto slots = grid.oversizedSlots();
  if (slots.empty()) return;
  sweep_.resize(slots.size());
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const Particle& p = particles[slots[k]];
    // NaN sorts first, so the order stays strict.
    const double left = std::isnan(p.x) ? -std::numeric_limits<double>::infinity() : p.x - p.radius;
    sweep_[k] = {left, p.x + p.radius, slots[k]};
  }
  std::sort(sweep_.begin(), sweep_.end(), [](const SweepEntry& a, const SweepEntry& b) {
    return std::tie(a.left, a.slot) < std::tie(b.left, b.slot);
  });
  const int columns = grid.columns();
  for (std::size_t k = 0; k < sweep_.size(); ++k) {
    const std::uint32_t a = sweep_[k].slot;
    const Particle& pa = particles[a];
    // A grid ball overlaps `a` only within a.radius + oversizedRadius of its centre; cellAt
    // clamps as the grid does, so balls outside the box are found in the border cells.
    const double reach = pa.radius + grid.oversizedRadius();
    const auto low =
        static_cast<int>(grid.cellAt(pa.x - reach, pa.y - reach, common::CellOrder::FromLowerLeft));
    const auto high =
        static_cast<int>(grid.cellAt(pa.x + reach, pa.y + reach, common::CellOrder::FromLowerLeft));
    for (int row = low / columns; row <= high / columns; ++row) {
      meet(particles, a,
           grid.slotsIn(row * columns + low % columns, row * columns + high % columns + 1));
    }
    // Later entries start further right: once one starts beyond this ball's right edge, all do.
    for (std::size_t later = k + 1; later < sweep_.size() && sweep_[later].left < sweep_[k].right;
         ++later) {
      const std::uint32_t b = sweep_[later].slot;
      const Particle& pb = particles[b];
      if (overlap(pa, pb)) contacts_.push_back({a, b, pa.vx - pb.vx, pa.vy - pb.vy, 0});
    }
  }
}

void PairContacts::project(Particles& particles) {
  std::vector<Particle>& p = particles.particle;
  for (PairContact& contact : contacts_) {
    Particle& a = p[contact.a];
    Particle& b = p[contact.b];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double reach = a.radius + b.radius;
    const double distanceSquared = dx * dx + dy * dy;
    if (!(distanceSquared < reach * reach)) continue;  // C = d − reach ≥ 0: inactive
    const double distance = std::sqrt(distanceSquared);
    const Normal n = normalOf(a, b, dx, dy, distance);
    const double depth = reach - distance;  // m, −C
    const double shareA = shareOf(a, b);
    const double shareB = shareOf(b, a);
    a.x -= n.x * depth * shareA;
    a.y -= n.y * depth * shareA;
    b.x += n.x * depth * shareB;
    b.y += n.y * depth * shareB;
    contact.active = 1;
    particles.moved[contact.a] = 1;
    particles.moved[contact.b] = 1;
  }
}

void PairContacts::restitute(Particles& particles) {
  std::vector<Particle>& p = particles.particle;
  for (const PairContact& contact : contacts_) {
    if (contact.active == 0) continue;
    Particle& a = p[contact.a];
    Particle& b = p[contact.b];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const Normal n = normalOf(a, b, dx, dy, std::hypot(dx, dy));
    const double normalVelocity = n.x * (a.vx - b.vx) + n.y * (a.vy - b.vy);  // m/s
    const double before = n.x * contact.relativeVx + n.y * contact.relativeVy;
    const double target = std::min(-before, 0.0);  // e = 1
    const double change = target - normalVelocity;
    const double shareA = shareOf(a, b);
    const double shareB = shareOf(b, a);
    a.vx += n.x * change * shareA;
    a.vy += n.y * change * shareA;
    b.vx -= n.x * change * shareB;
    b.vy -= n.y * change * shareB;
  }
}

std::uint64_t PairContacts::countEvents(const Particles& particles, ContactMemory& memory,
                                        std::uint32_t now) const {
  std::uint64_t events = 0;
  for (const PairContact& contact : contacts_) {
    if (contact.active == 0) continue;
    const std::uint32_t idA = particles.id[contact.a];
    const std::uint32_t idB = particles.id[contact.b];
    const std::uint32_t first = std::min(idA, idB);
    const std::uint32_t second = std::max(idA, idB);
    if (!memory.recall(first, second, now)) {
      memory.add(first, second);
      ++events;
    }
  }
  return events;
}

std::size_t PairContacts::memoryBytes() const {
  return contacts_.capacity() * sizeof(PairContact) + sweep_.capacity() * sizeof(SweepEntry);
}

}  // namespace fooball::xpbd
