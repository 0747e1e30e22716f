#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "rgb_frame.h"

namespace fooball::video {

/// The 256 colours of a GIF recording, chosen once from its first frame and kept for every
/// frame: one palette lets the GIF encoder store only what changed from the frame before (a
/// small rectangle, the rest transparent), which keeps a box of moving balls small; a palette
/// per frame would store every frame whole. FooBall's pictures are flat colours on black, so
/// the first frame holds nearly every colour that follows: its colours take 192 entries
/// (median cut, weighted by how many pixels show each), and a 4×4×4 cube of evenly spaced
/// colours takes the other 64, for a colour that appears later (a chart line, a hot ball).
/// Pixels map to the nearest entry without dithering: dither would speckle the flat black and
/// make every frame differ everywhere.
class GifPalette {
 public:
  static constexpr std::size_t kSize = 256;

  explicit GifPalette(const RgbFrame& firstFrame);

  /// 0xAARRGGBB, alpha 0xFF: the layout of an AV_PIX_FMT_PAL8 frame's palette.
  const std::array<std::uint32_t, kSize>& colours() const { return colours_; }
  /// The entry nearest (r, g, b), looked up by the colour's top 5 bits a channel.
  std::uint8_t indexOf(std::uint8_t r, std::uint8_t g, std::uint8_t b);
  /// Writes `frame` as palette indices, `bytesPerLine` apart, into `indices`.
  void map(const RgbFrame& frame, std::uint8_t* indices, std::ptrdiff_t bytesPerLine);

 private:
  static constexpr std::size_t kBins = 1 << 15;  ///< 5 bits a channel
  static constexpr std::uint16_t kUnknown = 0xFFFF;

  std::uint8_t nearest(int r, int g, int b) const;

  std::array<std::uint32_t, kSize> colours_{};
  std::size_t count_ = 0;                    ///< entries in use
  std::array<std::uint16_t, kBins> lookup_;  ///< bin → entry, kUnknown until first asked
};

}  // namespace fooball::video
