// collideRows with the lane test four lanes at a time (LaneTest::Avx2).
//
// Everything this file includes is read first under the baseline instruction set, so the inline
// functions of those headers stay callable from the rest of the program; only what follows the
// target pragma — pair_search.h's copy of the pair search, and the lane test — is compiled for
// AVX2. On the standard gas at 100'000 balls, 1 thread, substeps = 1: 34.9 against 38.9 ns per
// ball-step for the scalar test (docs/performance.md).

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "balls.h"
#include "common/cell_lists.h"
#include "neighbour_slots.h"
#include "pair_collisions.h"

#pragma GCC push_options
#pragma GCC target("avx2")

#include "pair_search.h"

namespace fooball::elastic {

namespace {

/// Bit j set when `a` overlaps the ball in slot slots[j], j < kLanes, four lanes per
/// instruction: per lane the same operations as the scalar test — dx = b.x − a.x, dx·dx + dy·dy,
/// reach = a.radius + b.radius, !(d² ≥ reach²), which counts a NaN as an overlap — so the bits
/// are the same. A lambda, so that each use is inlined into the pair search.
const auto avx2OverlapMask = [](const Probe& a, std::span<const Ball> balls,
                                const std::uint32_t* slots) {
  static_assert(kLanes % 4 == 0);
  const __m256d ax = _mm256_set1_pd(a.x);
  const __m256d ay = _mm256_set1_pd(a.y);
  const __m256d ar = _mm256_set1_pd(a.radius);
  unsigned mask = 0;
  for (std::size_t first = 0; first < kLanes; first += 4) {
    const Ball& b0 = balls[slots[first]];
    const Ball& b1 = balls[slots[first + 1]];
    const Ball& b2 = balls[slots[first + 2]];
    const Ball& b3 = balls[slots[first + 3]];
    // A record's x and y are adjacent: load (x, y) of b0 and b2 into one register, of b1 and
    // b3 into another, and unpack within each 128-bit half into x0 x1 x2 x3 and y0 y1 y2 y3.
    const __m256d xy02 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&b0.x)), _mm_loadu_pd(&b2.x), 1);
    const __m256d xy13 =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&b1.x)), _mm_loadu_pd(&b3.x), 1);
    const __m256d dx = _mm256_sub_pd(_mm256_unpacklo_pd(xy02, xy13), ax);
    const __m256d dy = _mm256_sub_pd(_mm256_unpackhi_pd(xy02, xy13), ay);
    const __m256d distanceSquared = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const __m256d reach =
        _mm256_add_pd(ar, _mm256_set_pd(b3.radius, b2.radius, b1.radius, b0.radius));
    const __m256d reachSquared = _mm256_mul_pd(reach, reach);
    // "Not greater or equal, unordered": true for NaN, as !(d² >= reach²) is.
    const __m256d overlapping = _mm256_cmp_pd(distanceSquared, reachSquared, _CMP_NGE_UQ);
    mask |= static_cast<unsigned>(_mm256_movemask_pd(overlapping)) << first;
  }
  return mask;
};

}  // namespace

std::uint64_t collideRowsAvx2(std::span<Ball> balls, const common::CellLists& cells, int firstRow,
                              int endRow, NeighbourSlots& neighbours) {
  return collideRowsWith(balls, cells, firstRow, endRow, neighbours, avx2OverlapMask);
}

}  // namespace fooball::elastic

#pragma GCC pop_options
