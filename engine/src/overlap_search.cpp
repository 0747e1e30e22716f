#include "overlap_search.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace fooball {
namespace {

/// The level whose cells are the smallest power of two wider than the ball's diameter.
int levelOf(double radius) {
  int exponent = 0;
  std::frexp(2.0 * radius, &exponent);  // 2r = m·2^exponent with 0.5 ≤ m < 1
  return exponent;
}

/// floor(position / 2^level), clamped far outside any box: clamping keeps neighbouring cells
/// neighbours, so balls placed absurdly far out (walls off) are still compared, never lost.
std::int64_t cellCoordinate(double position, int level) {
  constexpr double kLimit = 0x1p60;
  const double scaled = std::floor(std::ldexp(position, -level));
  return static_cast<std::int64_t>(std::clamp(scaled, -kLimit, kLimit));
}

/// One ball in the cell of its level (cells of level L are 2^L m wide).
struct Entry {
  int level = 0;
  std::int64_t row = 0;
  std::int64_t column = 0;
  std::uint32_t ball = 0;

  auto cell() const { return std::tie(level, row, column); }
  friend bool operator<(const Entry& a, const Entry& b) {
    return std::tie(a.level, a.row, a.column, a.ball) < std::tie(b.level, b.row, b.column, b.ball);
  }
};

/// Searches the balls for a pair overlapping too deeply, in a fixed order.
class OverlapSearch {
 public:
  OverlapSearch(std::span<const BallDef> balls, double slop) : slop_(slop) {
    entries_.reserve(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const int level = levelOf(balls[i].radius);
      entries_.push_back({level, cellCoordinate(balls[i].position.y, level),
                          cellCoordinate(balls[i].position.x, level),
                          static_cast<std::uint32_t>(i)});
    }
    // Sorted by cell, each level is a grid of rows: a sweep along it meets neighbouring cells
    // close together in memory.
    std::sort(entries_.begin(), entries_.end());
    // The balls copied into that order, so the sweep reads memory in sequence too.
    sorted_.reserve(entries_.size());
    for (std::size_t e = 0; e < entries_.size(); ++e) {
      sorted_.push_back({balls[entries_[e].ball].position, balls[entries_[e].ball].radius});
      if (e == 0 || entries_[e].level != entries_[e - 1].level) levelStarts_.push_back(e);
    }
    levelStarts_.push_back(entries_.size());
  }

  std::optional<DeepOverlap> run() {
    // Pairs within each level first, then each ball against the bigger levels. Stopping at the
    // first deep overlap keeps both linear: until then every cell holds only balls that do not
    // overlap much, and so only a handful of them.
    for (std::size_t level = 0; level + 1 < levelStarts_.size() && !found_; ++level)
      sweepLevel(levelStarts_[level], levelStarts_[level + 1]);
    for (std::size_t level = 0; level + 1 < levelStarts_.size() && !found_; ++level) {
      for (std::size_t e = levelStarts_[level]; e < levelStarts_[level + 1] && !found_; ++e) {
        for (std::size_t bigger = level + 1; bigger + 1 < levelStarts_.size(); ++bigger)
          compareWithLevel(e, levelStarts_[bigger], levelStarts_[bigger + 1]);
      }
    }
    return found_;
  }

 private:
  /// Entries `a` and `b`, by their place in the sorted order.
  void consider(std::size_t a, std::size_t b) {
    const Disk& first = sorted_[a];
    const Disk& second = sorted_[b];
    const double smaller = std::min(first.radius, second.radius);
    // Too deep when the distance is below reach - slop·smaller (> 0): compared squared, so
    // only a reported pair pays for a square root.
    const double closest = first.radius + second.radius - slop_ * smaller;
    if (lengthSquared(first.position - second.position) >= closest * closest) return;
    const double depth = first.radius + second.radius - length(first.position - second.position);
    if (depth <= slop_ * smaller) return;
    const std::uint32_t i = entries_[a].ball;
    const std::uint32_t j = entries_[b].ball;
    const DeepOverlap pair{std::min(i, j), std::max(i, j), depth / smaller};
    if (!found_ || std::pair(pair.first, pair.second) < std::pair(found_->first, found_->second))
      found_ = pair;
  }

  /// The end of the cell that starts at `start`.
  std::size_t cellEnd(std::size_t start, std::size_t end) const {
    std::size_t e = start + 1;
    while (e < end && entries_[e].cell() == entries_[start].cell())
      ++e;
    return e;
  }

  void considerCells(std::size_t aStart, std::size_t aEnd, std::size_t bStart, std::size_t bEnd) {
    for (std::size_t a = aStart; a < aEnd; ++a) {
      for (std::size_t b = bStart; b < bEnd; ++b)
        consider(a, b);
    }
  }

  /// Every pair of one level's balls in the same or adjacent cells, each pair of cells once:
  /// a cell with itself, with the cell to its right, and with the three cells above.
  void sweepLevel(std::size_t begin, std::size_t end) {
    std::size_t above = begin;  // the first entry not before (row + 1, column - 1)
    for (std::size_t start = begin, stop; start < end && !found_; start = stop) {
      stop = cellEnd(start, end);
      const Entry& cell = entries_[start];
      for (std::size_t a = start; a < stop; ++a) {
        for (std::size_t b = a + 1; b < stop; ++b)
          consider(a, b);
      }
      if (stop < end && entries_[stop].row == cell.row && entries_[stop].column == cell.column + 1)
        considerCells(start, stop, stop, cellEnd(stop, end));
      while (above < end && std::pair(entries_[above].row, entries_[above].column) <
                                std::pair(cell.row + 1, cell.column - 1))
        ++above;
      for (std::size_t e = above;
           e < end && entries_[e].row == cell.row + 1 && entries_[e].column <= cell.column + 1;) {
        const std::size_t next = cellEnd(e, end);
        considerCells(start, stop, e, next);
        e = next;
      }
    }
  }

  /// The ball of entry `small` against the balls of a bigger level in the 3 × 3 cells around
  /// it (cells there are wider than both balls' radii together).
  void compareWithLevel(std::size_t small, std::size_t begin, std::size_t end) {
    const int level = entries_[begin].level;
    const Vec2 p = sorted_[small].position;
    const std::int64_t row = cellCoordinate(p.y, level);
    const std::int64_t column = cellCoordinate(p.x, level);
    for (std::int64_t r = row - 1; r <= row + 1; ++r) {
      auto e = std::lower_bound(entries_.begin() + begin, entries_.begin() + end,
                                std::pair(r, column - 1), [](const Entry& entry, const auto& key) {
                                  return std::pair(entry.row, entry.column) < key;
                                });
      for (; e != entries_.begin() + end && e->row == r && e->column <= column + 1; ++e)
        consider(small, static_cast<std::size_t>(e - entries_.begin()));
    }
  }

  struct Disk {
    Vec2 position;
    double radius = 0.0;
  };

  double slop_;
  std::vector<Entry> entries_;            ///< by (level, row, column, ball)
  std::vector<std::size_t> levelStarts_;  ///< where each level begins, and the end
  std::vector<Disk> sorted_;              ///< the balls, in the order of entries_
  std::optional<DeepOverlap> found_;
};

}  // namespace

std::optional<DeepOverlap> findDeepOverlap(std::span<const BallDef> balls, double slop) {
  return OverlapSearch(balls, slop).run();
}

}  // namespace fooball
