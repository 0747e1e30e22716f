#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/cell_lists.h"
#include "contact_memory.h"
#include "particles.h"

namespace fooball::xpbd {

/// One overlapping pair found at the start of a substep's solve, on the predicted centres.
struct PairContact {
  std::uint32_t a, b;             ///< slots
  double relativeVx, relativeVy;  ///< m/s, v_a − v_b before the solve (v̄ of Müller 2020 §3.6)
  std::uint32_t active = 0;       ///< 1: projected at least once in this substep
};

/// The ball–ball non-penetration constraints of one substep (compliance 0): found once per
/// substep on the predicted centres, projected `iterations` times Gauss–Seidel, then given
/// `iterations` restitution passes. Contacts are strict overlaps (d < r_a + r_b), so a row of
/// balls with any gap between them passes momentum on one pair per substep, as hard spheres do;
/// a row that touches only to rounding overlaps by ulps, is in contact all at once and shares
/// the momentum out (docs/accuracy.md, Newton's cradle).
class PairContacts {
 public:
  /// Every overlapping pair of `particles`, in a fixed order: grid cells row by row, each ball
  /// against the later balls of its cell, the cell to its right and the three cells above; then
  /// each oversized ball against the grid balls within its reach and the later oversized balls
  /// it meets along x (a sweep over their left edges).
  void find(std::span<const Particle> particles, const common::CellLists& grid);

  /// One Gauss–Seidel pass: every contact still overlapping is pushed apart to touching along
  /// the line of centres, each ball moved in proportion to its inverse mass, so the centre of
  /// mass stays put (Δλ = −C/(w_a + w_b) with compliance 0). Marks the balls it moves.
  void project(Particles& particles);

  /// One velocity pass over the contacts that were active (Müller 2020 §3.6, restitution
  /// e = 1): with n from a to b on the solved centres and v_n = n·(v_a − v_b) (> 0
  /// approaching), sets v_n to min(−e·v̄_n, 0), v̄_n the normal velocity before the solve, by an
  /// impulse weighted by inverse mass: an approaching pair leaves at its approach speed, a pair
  /// that was not approaching keeps no normal velocity from the push that separated it.
  void restitute(Particles& particles);

  /// The contact events begun in substep `now`: active contacts that `memory` (scene indices)
  /// does not hold from the substeps before.
  std::uint64_t countEvents(const Particles& particles, ContactMemory& memory,
                            std::uint32_t now) const;

  std::size_t size() const { return contacts_.size(); }
  void clear() { contacts_.clear(); }
  /// Room for `count` contacts, so that steady state does not allocate.
  void reserve(std::size_t count) { contacts_.reserve(count); }
  std::size_t memoryBytes() const;

 private:
  /// An oversized ball's extent along x when `find` begins, for its sweep.
  struct SweepEntry {
    double left;
    double right;
    std::uint32_t slot;
  };

  void meet(std::span<const Particle> particles, std::uint32_t a,
            std::span<const std::uint32_t> candidates);
  void findOversized(std::span<const Particle> particles, const common::CellLists& grid);

  std::vector<PairContact> contacts_;
  std::vector<SweepEntry> sweep_;
};

}  // namespace fooball::xpbd
