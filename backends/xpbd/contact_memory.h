#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace fooball::xpbd {

/// How long (substeps) a ball–ball contact is remembered after its last active substep: a contact
/// that is active again within this many substeps continues the same contact event rather than
/// starting a new one (wall contacts follow common/wall_touches.h). A ball resting on another
/// ball under gravity is pressed in (by g·h²) and pushed out every other substep or so: one
/// resting contact, not a collision per substep. A real collision leaves the contact for many
/// substeps (the pair separates at the approach speed), so a new hit of the same pair within this
/// window is rare and would be missed: that is the price of counting a resting contact once.
/// Measured over 20 s at the defaults: the gas preset counts 8'325, 8'313, 8'291 and 8'272
/// ball–ball collisions with a memory of 1, 2, 4 and 7 substeps (exact: 8'329); the rain preset,
/// settling into a pile, 173'348, 169'526, 164'583 and 158'416 (exact, which counts every bounce
/// of a Zeno sequence: 176'122).
inline constexpr std::uint32_t kContactMemory = 4;

/// Which ball pairs (by scene index) were in contact in the last kContactMemory substeps: a
/// compressed-row table, each ball's later partners after its start, rebuilt by a counting sort
/// after every substep with contacts (O(N + contacts), no allocation once the buffers have grown
/// to the scene's working size).
class ContactMemory {
 public:
  /// Forgets everything and sizes the table for `balls` balls.
  void reset(std::size_t balls);

  /// Whether the pair (first, second), first < second, was in contact within the memory before
  /// substep `now`; if so, the contact is refreshed to `now`. Otherwise the caller adds it with
  /// add().
  bool recall(std::uint32_t first, std::uint32_t second, std::uint32_t now);

  /// A contact of substep `now` that recall() did not know.
  void add(std::uint32_t first, std::uint32_t second) { fresh_.push_back({first, second, 0}); }

  /// After substep `now`: keeps the contacts active within the memory, adds the fresh ones.
  void commit(std::uint32_t now);

  std::size_t memoryBytes() const;

 private:
  struct Entry {
    std::uint32_t first;   ///< scene index, the smaller of the pair (only in fresh_)
    std::uint32_t second;  ///< scene index, the larger
    std::uint32_t stamp;   ///< substep of the last contact
  };

  std::vector<std::uint32_t> start_;  ///< per ball + 1: where its partners begin in entries_
  std::vector<Entry> entries_;
  std::vector<Entry> scratch_;
  std::vector<Entry> fresh_;
  std::uint32_t balls_ = 0;
};

}  // namespace fooball::xpbd
