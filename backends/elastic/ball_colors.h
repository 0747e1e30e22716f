#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "fooball/scene.h"

namespace fooball::elastic {

/// The balls' colours, by scene index. Drawing only, so kept out of the hot arrays, and stored
/// as the exceptions to the scene format's default colour for each index (defaultBallColor):
/// random balls and the standard gas take the defaults and cost nothing, where a colour per
/// ball would cost 4 bytes each.
class BallColors {
 public:
  void assign(std::span<const BallDef> balls);
  std::uint32_t operator[](std::size_t index) const;
  void set(std::size_t index, std::uint32_t color);

  std::size_t memoryBytes() const { return exceptions_.capacity() * sizeof(Exception); }

 private:
  using Exception = std::pair<std::uint32_t, std::uint32_t>;  ///< (scene index, 0xRRGGBB)
  std::vector<Exception> exceptions_;                         ///< sorted by index
};

}  // namespace fooball::elastic
