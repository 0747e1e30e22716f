#include "gif_palette.h"

#include <gtest/gtest.h>

#include <vector>

namespace fooball::video {
namespace {

TEST(GifPalette, KeepsEveryColourOfAFewColouredFirstFrame) {
  // Black, white, a ball's orange and a run's blue: each its own entry, exactly.
  const std::vector<std::uint8_t> rgb = {0,   0,   0,  255, 255, 255,  //
                                         224, 160, 48, 60,  140, 230};
  GifPalette palette({rgb.data(), 4, 1, 12});
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    const std::uint32_t colour = palette.colours()[palette.indexOf(rgb[i], rgb[i + 1], rgb[i + 2])];
    EXPECT_EQ(colour, 0xFF000000u | (std::uint32_t(rgb[i]) << 16) |
                          (std::uint32_t(rgb[i + 1]) << 8) | rgb[i + 2]);
  }
}

TEST(GifPalette, MapsALaterColourToANearEntry) {
  const std::vector<std::uint8_t> black(3 * 16, 0);
  GifPalette palette({black.data(), 16, 1, 48});
  // Pure green never appeared: the cube's nearest entry is pure green.
  EXPECT_EQ(palette.colours()[palette.indexOf(0, 250, 0)], 0xFF00FF00u);
  std::uint8_t out[16];
  palette.map({black.data(), 16, 1, 48}, out, 16);
  EXPECT_EQ(palette.colours()[out[7]], 0xFF000000u);
}

}  // namespace
}  // namespace fooball::video
