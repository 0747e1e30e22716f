#pragma once

#include <cstddef>

namespace fooball::common {

/// The part [begin, end) of `count` items that worker `worker` of `workers` takes: contiguous
/// and as equal as can be.
struct Share {
  std::size_t begin;
  std::size_t end;
};
inline Share shareOf(std::size_t count, int worker, int workers) {
  const auto part = [&](int w) { return count * static_cast<std::size_t>(w) / workers; };
  return {part(worker), part(worker + 1)};
}

}  // namespace fooball::common
