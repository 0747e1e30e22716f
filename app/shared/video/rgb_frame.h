#pragma once

#include <cstddef>
#include <cstdint>

namespace fooball::video {

/// One picture handed to the encoder: `height` rows of `width` pixels, 3 bytes each in the order
/// R, G, B (QImage::Format_RGB888's layout), rows `bytesPerLine` apart. The caller owns the
/// pixels; the encoder reads them during the call only.
struct RgbFrame {
  const std::uint8_t* pixels = nullptr;
  int width = 0;                    ///< px
  int height = 0;                   ///< px
  std::ptrdiff_t bytesPerLine = 0;  ///< ≥ 3·width
};

}  // namespace fooball::video
