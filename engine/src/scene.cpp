#include "fooball/scene.h"

#include <cmath>

namespace fooball {
namespace {

/// 0..255 from a channel in [0, 1].
std::uint32_t channelByte(double channel) {
  return static_cast<std::uint32_t>(std::lround(channel * 255.0));
}

}  // namespace

std::uint32_t defaultBallColor(std::size_t index) {
  // Hues a golden-ratio turn apart: each new ball lands in the widest gap the earlier ones
  // left, so any run of neighbours stays distinct. Integer arithmetic (a 64-bit fraction of a
  // turn) makes ball 1'000'000 as exact as ball 1; the start, 40°, is FooBall's amber.
  constexpr std::uint64_t kGoldenTurn = 0x9e3779b97f4a7c15u;  ///< 2^64 / φ
  constexpr std::uint64_t kAmberTurn = 0x1c71c71c71c71c72u;   ///< 2^64 / 9 = 40°
  const std::uint64_t turn = kAmberTurn + static_cast<std::uint64_t>(index) * kGoldenTurn;
  const double sextants = static_cast<double>(turn >> 11) * 0x1p-53 * 6.0;  // hue in [0, 6)

  // HSV → RGB, saturated enough to tell apart and bright enough for a black background.
  constexpr double kSaturation = 0.65;
  constexpr double kValue = 0.95;
  const int sextant = static_cast<int>(sextants);
  const double f = sextants - sextant;
  const double v = kValue;
  const double p = kValue * (1.0 - kSaturation);
  const double q = kValue * (1.0 - kSaturation * f);
  const double t = kValue * (1.0 - kSaturation * (1.0 - f));
  const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  const double* channels = rgb[sextant];
  return channelByte(channels[0]) << 16 | channelByte(channels[1]) << 8 | channelByte(channels[2]);
}

}  // namespace fooball
