#include "overlap_search.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
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

/// The rows and columns one level's balls occupy.
struct LevelBounds {
  int level = 0;
  std::int64_t firstRow = 0, lastRow = 0, firstColumn = 0, lastColumn = 0;
  std::size_t firstCell = 0;  ///< where the level's cells start in the count of all cells

  double cellCount() const {
    return (double(lastRow - firstRow) + 1.0) * (double(lastColumn - firstColumn) + 1.0);
  }
};

/// A counting sort over the cells the balls span is worth it when they are no more than this
/// many per ball (plus a few): a dense gas spans about 2–7 cells per ball. Sparse or scattered
/// balls, or many sizes, take the comparison sort instead.
constexpr double kMaxCellsPerBall = 8.0;
constexpr double kExtraCells = 1024.0;
constexpr std::size_t kMaxCountedLevels = 16;

/// Sorts `entries` (made in ball order) by (level, row, column, ball), as std::sort would.
/// The counting sort is linear and keeps the ball order within a cell, so it gives the same
/// order as the comparison sort, which took about half of a 100,000-ball gas's overlap search.
void sortByCell(std::vector<Entry>& entries) {
  std::vector<LevelBounds> levels;
  for (const Entry& e : entries) {
    auto found = std::find_if(levels.begin(), levels.end(),
                              [&](const LevelBounds& b) { return b.level == e.level; });
    if (found == levels.end()) {
      if (levels.size() == kMaxCountedLevels) break;
      levels.push_back({e.level, e.row, e.row, e.column, e.column, 0});
      continue;
    }
    found->firstRow = std::min(found->firstRow, e.row);
    found->lastRow = std::max(found->lastRow, e.row);
    found->firstColumn = std::min(found->firstColumn, e.column);
    found->lastColumn = std::max(found->lastColumn, e.column);
  }
  std::sort(levels.begin(), levels.end(),
            [](const LevelBounds& a, const LevelBounds& b) { return a.level < b.level; });
  double cells = 0.0;
  for (LevelBounds& bounds : levels) {
    bounds.firstCell = static_cast<std::size_t>(cells);
    cells += bounds.cellCount();
  }
  if (levels.size() == kMaxCountedLevels ||
      cells > kMaxCellsPerBall * double(entries.size()) + kExtraCells) {
    std::sort(entries.begin(), entries.end());
    return;
  }
  const auto cellOf = [&](const Entry& e) {
    const LevelBounds& bounds =
        levels.size() == 1 ? levels.front()
                           : *std::find_if(levels.begin(), levels.end(), [&](const LevelBounds& b) {
                               return b.level == e.level;
                             });
    const auto columns = static_cast<std::size_t>(bounds.lastColumn - bounds.firstColumn + 1);
    return bounds.firstCell + static_cast<std::size_t>(e.row - bounds.firstRow) * columns +
           static_cast<std::size_t>(e.column - bounds.firstColumn);
  };
  std::vector<std::uint32_t> starts(static_cast<std::size_t>(cells) + 1, 0);
  for (const Entry& e : entries)
    ++starts[cellOf(e) + 1];
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  std::vector<Entry> sorted(entries.size());
  for (const Entry& e : entries)
    sorted[starts[cellOf(e)]++] = e;
  entries = std::move(sorted);
}

/// One ball as the search reads it.
struct Disk {
  Vec2 position;
  double radius = 0.0;
};

/// The balls sorted into grids, one per power-of-two size, and the pairs that may overlap
/// there, in a fixed order.
class SizeClassGrids {
 public:
  /// `diskOf(i)` is ball i, for i < count.
  template <class DiskOf>
  SizeClassGrids(std::size_t count, DiskOf diskOf) {
    entries_.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Disk disk = diskOf(i);
      const int level = levelOf(disk.radius);
      entries_.push_back({level, cellCoordinate(disk.position.y, level),
                          cellCoordinate(disk.position.x, level), static_cast<std::uint32_t>(i)});
    }
    // Sorted by cell, each level is a grid of rows: a sweep along it meets neighbouring cells
    // close together in memory.
    sortByCell(entries_);
    // The balls copied into that order, so the sweep reads memory in sequence too.
    sorted_.reserve(entries_.size());
    for (std::size_t e = 0; e < entries_.size(); ++e) {
      sorted_.push_back(diskOf(entries_[e].ball));
      if (e == 0 || entries_[e].level != entries_[e - 1].level) levelStarts_.push_back(e);
    }
    levelStarts_.push_back(entries_.size());
  }

  /// Calls visit(i, j, disk i, disk j) for every pair of balls i, j that can overlap: pairs
  /// within each level first, then each ball against the bigger levels. Stops, at the end of a
  /// cell, once done() is true.
  template <class Visit, class Done>
  void forEachNearbyPair(Visit&& visit, Done&& done) {
    const auto consider = [&](std::size_t a, std::size_t b) {
      visit(entries_[a].ball, entries_[b].ball, sorted_[a], sorted_[b]);
    };
    for (std::size_t level = 0; level + 1 < levelStarts_.size() && !done(); ++level)
      sweepLevel(levelStarts_[level], levelStarts_[level + 1], consider, done);
    for (std::size_t level = 0; level + 1 < levelStarts_.size() && !done(); ++level) {
      for (std::size_t e = levelStarts_[level]; e < levelStarts_[level + 1] && !done(); ++e) {
        for (std::size_t bigger = level + 1; bigger + 1 < levelStarts_.size(); ++bigger)
          compareWithLevel(e, levelStarts_[bigger], levelStarts_[bigger + 1], consider);
      }
    }
  }

  /// The pairs of forEachNearbyPair, in an order that suits the sizes rather than a fixed one:
  /// across two levels, each bigger ball meets the smaller balls in the rows it covers when that
  /// takes fewer searches than each smaller ball meeting the bigger level, as when a few big
  /// balls lie among many small ones.
  template <class Visit>
  void forEachNearbyPairAnyOrder(Visit&& visit) {
    const auto consider = [&](std::size_t a, std::size_t b) {
      visit(entries_[a].ball, entries_[b].ball, sorted_[a], sorted_[b]);
    };
    const auto never = [] { return false; };
    const std::size_t levels = levelStarts_.size() - 1;
    for (std::size_t level = 0; level < levels; ++level)
      sweepLevel(levelStarts_[level], levelStarts_[level + 1], consider, never);
    for (std::size_t level = 0; level < levels; ++level) {
      const std::size_t begin = levelStarts_[level];
      const std::size_t end = levelStarts_[level + 1];
      for (std::size_t bigger = level + 1; bigger < levels; ++bigger) {
        const std::size_t biggerBegin = levelStarts_[bigger];
        const std::size_t biggerEnd = levelStarts_[bigger + 1];
        double rowSearches = 0.0;  // by the bigger balls; the smaller ones need 3 each
        for (std::size_t e = biggerBegin; e < biggerEnd; ++e)
          rowSearches += static_cast<double>(coveredRows(e, begin, end).size());
        if (rowSearches < 3.0 * static_cast<double>(end - begin)) {
          for (std::size_t e = biggerBegin; e < biggerEnd; ++e)
            compareWithSmallerLevel(e, begin, end, consider);
        } else {
          for (std::size_t e = begin; e < end; ++e)
            compareWithLevel(e, biggerBegin, biggerEnd, consider);
        }
      }
    }
  }

 private:
  /// The end of the cell that starts at `start`.
  std::size_t cellEnd(std::size_t start, std::size_t end) const {
    std::size_t e = start + 1;
    while (e < end && entries_[e].cell() == entries_[start].cell())
      ++e;
    return e;
  }

  template <class Consider>
  static void considerCells(std::size_t aStart, std::size_t aEnd, std::size_t bStart,
                            std::size_t bEnd, Consider& consider) {
    for (std::size_t a = aStart; a < aEnd; ++a) {
      for (std::size_t b = bStart; b < bEnd; ++b)
        consider(a, b);
    }
  }

  /// Every pair of one level's balls in the same or adjacent cells, each pair of cells once:
  /// a cell with itself, with the cell to its right, and with the three cells above.
  template <class Consider, class Done>
  void sweepLevel(std::size_t begin, std::size_t end, Consider& consider, Done& done) {
    std::size_t above = begin;  // the first entry not before (row + 1, column - 1)
    for (std::size_t start = begin, stop; start < end && !done(); start = stop) {
      stop = cellEnd(start, end);
      const Entry& cell = entries_[start];
      for (std::size_t a = start; a < stop; ++a) {
        for (std::size_t b = a + 1; b < stop; ++b)
          consider(a, b);
      }
      if (stop < end && entries_[stop].row == cell.row && entries_[stop].column == cell.column + 1)
        considerCells(start, stop, stop, cellEnd(stop, end), consider);
      while (above < end && std::pair(entries_[above].row, entries_[above].column) <
                                std::pair(cell.row + 1, cell.column - 1))
        ++above;
      for (std::size_t e = above;
           e < end && entries_[e].row == cell.row + 1 && entries_[e].column <= cell.column + 1;) {
        const std::size_t next = cellEnd(e, end);
        considerCells(start, stop, e, next, consider);
        e = next;
      }
    }
  }

  /// The ball of entry `small` against the balls of a bigger level in the 3 × 3 cells around
  /// it (cells there are wider than both balls' radii together).
  template <class Consider>
  void compareWithLevel(std::size_t small, std::size_t begin, std::size_t end, Consider& consider) {
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

  /// Rows [first, end) and columns [first, last] of the smaller level's cells (entries [begin,
  /// end)) that hold every ball of that level overlapping the ball of entry `big`.
  struct CellRange {
    std::int64_t firstRow, endRow, firstColumn, lastColumn;
    std::size_t size() const { return endRow > firstRow ? std::size_t(endRow - firstRow) : 0; }
  };
  CellRange coveredRows(std::size_t big, std::size_t begin, std::size_t end) const {
    const int level = entries_[begin].level;
    const Disk& disk = sorted_[big];
    // A ball of the smaller level has a radius below half its cell.
    const double reach = disk.radius + std::ldexp(0.5, level);
    // Only rows the level has: a huge ball covers no more rows than its level holds.
    const std::int64_t firstRow =
        std::max(cellCoordinate(disk.position.y - reach, level), entries_[begin].row);
    const std::int64_t lastRow =
        std::min(cellCoordinate(disk.position.y + reach, level), entries_[end - 1].row);
    return {firstRow, lastRow + 1, cellCoordinate(disk.position.x - reach, level),
            cellCoordinate(disk.position.x + reach, level)};
  }

  /// The ball of entry `big` against the balls of the smaller level (entries [begin, end)) in
  /// the cells its reach covers.
  template <class Consider>
  void compareWithSmallerLevel(std::size_t big, std::size_t begin, std::size_t end,
                               Consider& consider) {
    const CellRange cells = coveredRows(big, begin, end);
    auto e = entries_.begin() + static_cast<std::ptrdiff_t>(begin);
    for (std::int64_t r = cells.firstRow; r < cells.endRow; ++r) {
      e = std::lower_bound(e, entries_.begin() + static_cast<std::ptrdiff_t>(end),
                           std::pair(r, cells.firstColumn),
                           [](const Entry& entry, const auto& key) {
                             return std::pair(entry.row, entry.column) < key;
                           });
      for (; e != entries_.begin() + static_cast<std::ptrdiff_t>(end) && e->row == r &&
             e->column <= cells.lastColumn;
           ++e)
        consider(static_cast<std::size_t>(e - entries_.begin()), big);
    }
  }

  std::vector<Entry> entries_;            ///< by (level, row, column, ball)
  std::vector<std::size_t> levelStarts_;  ///< where each level begins, and the end
  std::vector<Disk> sorted_;              ///< the balls, in the order of entries_
};

}  // namespace

std::optional<DeepOverlap> findDeepOverlap(std::span<const BallDef> balls, double slop) {
  SizeClassGrids grids(balls.size(), [&](std::size_t i) {
    return Disk{balls[i].position, balls[i].radius};
  });
  // Stopping at the first deep overlap keeps the search linear: until then every cell holds
  // only balls that do not overlap much, and so only a handful of them.
  std::optional<DeepOverlap> found;
  grids.forEachNearbyPair(
      [&](std::uint32_t i, std::uint32_t j, const Disk& first, const Disk& second) {
        const double smaller = std::min(first.radius, second.radius);
        // Too deep when the distance is below reach - slop·smaller (> 0): compared squared, so
        // only a reported pair pays for a square root.
        const double closest = first.radius + second.radius - slop * smaller;
        if (lengthSquared(first.position - second.position) >= closest * closest) return;
        const double depth =
            first.radius + second.radius - length(first.position - second.position);
        if (depth <= slop * smaller) return;
        const DeepOverlap pair{std::min(i, j), std::max(i, j), depth / smaller};
        if (!found || std::pair(pair.first, pair.second) < std::pair(found->first, found->second))
          found = pair;
      },
      [&] { return found.has_value(); });
  return found;
}

std::optional<DeepOverlap> deepestOverlap(std::span<const BallDef> balls) {
  SizeClassGrids grids(balls.size(), [&](std::size_t i) {
    return Disk{balls[i].position, balls[i].radius};
  });
  std::optional<DeepOverlap> deepest;
  grids.forEachNearbyPairAnyOrder(
      [&](std::uint32_t i, std::uint32_t j, const Disk& first, const Disk& second) {
        const double reach = first.radius + second.radius;
        const double distanceSquared = lengthSquared(first.position - second.position);
        if (distanceSquared >= reach * reach) return;
        const double depth = reach - std::sqrt(distanceSquared);
        const DeepOverlap pair{std::min(i, j), std::max(i, j),
                               depth / std::min(first.radius, second.radius)};
        // Depth first, then the indices: the same pair whatever order the grids visit them in.
        if (!deepest || pair.depthFraction > deepest->depthFraction ||
            (pair.depthFraction == deepest->depthFraction &&
             std::pair(pair.first, pair.second) < std::pair(deepest->first, deepest->second))) {
          deepest = pair;
        }
      });
  return deepest;
}

double deepestPairOverlap(std::span<const Vec2> positions, std::span<const double> radii) {
  SizeClassGrids grids(positions.size(), [&](std::size_t i) {
    return Disk{positions[i], radii[i]};
  });
  double deepest = 0.0;
  grids.forEachNearbyPairAnyOrder(
      [&](std::uint32_t, std::uint32_t, const Disk& first, const Disk& second) {
        const double reach = first.radius + second.radius;
        const double distanceSquared = lengthSquared(first.position - second.position);
        if (distanceSquared >= reach * reach) return;
        const double depth = reach - std::sqrt(distanceSquared);
        deepest = std::max(deepest, depth / std::min(first.radius, second.radius));
      });
  return deepest;
}

}  // namespace fooball
