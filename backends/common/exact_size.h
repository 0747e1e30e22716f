#pragma once

#include <cstddef>
#include <vector>

namespace fooball::common {

/// Resizes `array` to `size` and gives back the capacity beyond it: a backend's buffers follow
/// the scene, so memory is released when a scene shrinks (the benchmarks' bytes per ball).
template <class T>
void resizeExactly(std::vector<T>& array, std::size_t size) {
  array.resize(size);
  array.shrink_to_fit();
}

}  // namespace fooball::common
