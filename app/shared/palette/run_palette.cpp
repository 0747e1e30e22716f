#include "run_palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fooball/run_group.h"
#include "registry.h"

namespace fooball::colours {

namespace {

/// The eight hues compare mode has had since it took eight runs: runs 0 and 1 orange and cyan,
/// the rest round the hue circle between them, alternating warm and cool so that neighbouring
/// runs differ most.
constexpr std::array<QRgb, 8> kFirstColours{
    0xffa726,  // orange
    0x26c6da,  // cyan
    0xe040fb,  // magenta
    0x9ce04c,  // lime
    0xff5252,  // red
    0x5c8dff,  // blue
    0xffee58,  // yellow
    0x69f0ae,  // green
};
static_assert(kFirstColours.size() == RunGroup::kMaxRuns);

/// The white of the one-run total curve and the markers: no colour may come close to it either.
constexpr QRgb kWhite = 0xf5f5f5;

/// Below this relative luminance (WCAG) a colour's contrast with the near-black plot (#050507)
/// is under 4.5, the least for text.
constexpr double kLeastLuminance = 0.18;
/// QColor's HSV saturation (0-255) below which a colour reads as a grey, like the baseline's.
constexpr int kLeastSaturation = 100;

double distance(const QColor& a, const QColor& b) {
  return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
}

double luminance(const QColor& colour) {
  const auto linear = [](double channel) {
    return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(colour.redF()) + 0.7152 * linear(colour.greenF()) +
         0.0722 * linear(colour.blueF());
}

const std::vector<QColor>& colours() {
  static const std::vector<QColor> palette =
      distinctColours(std::max(RunGroup::kMaxRuns, registeredBackends().size()));
  return palette;
}

}  // namespace

std::vector<QColor> distinctColours(std::size_t count) {
  std::vector<QColor> colours;
  for (const QRgb rgb : kFirstColours)
    colours.emplace_back(rgb);
  // Greedy farthest-point choice (in RGB) over hues every 6° at three lightnesses.
  std::vector<QColor> candidates;
  for (int hue = 0; hue < 360; hue += 6) {
    for (const float lightness : {0.6f, 0.7f, 0.8f}) {
      const QColor candidate = QColor::fromHslF(float(hue) / 360.0f, 0.9f, lightness).toRgb();
      // Readable on black, and a hue rather than a grey (light colours lose saturation).
      if (luminance(candidate) >= kLeastLuminance && candidate.saturation() >= kLeastSaturation)
        candidates.push_back(candidate);
    }
  }
  const QColor white(kWhite);
  while (colours.size() < count) {
    const auto nearest = [&](const QColor& candidate) {
      double least = std::min(distance(candidate, neutralColour()), distance(candidate, white));
      for (const QColor& chosen : colours)
        least = std::min(least, distance(candidate, chosen));
      return least;
    };
    colours.push_back(*std::ranges::max_element(candidates, {}, nearest));
  }
  return colours;
}

int colourCount() {
  return static_cast<int>(colours().size());
}

QColor runColour(int runIndex) {
  const int count = colourCount();
  return colours()[static_cast<std::size_t>(((runIndex % count) + count) % count)];
}

QColor backendColour(std::string_view backend) {
  const auto backends = registeredBackends();
  for (std::size_t index = 0; index < backends.size(); ++index) {
    if (backends[index].name == backend) return colours()[index];
  }
  return neutralColour();
}

QColor neutralColour() {
  return QColor(0x9e, 0x9e, 0x9e);
}

}  // namespace fooball::colours
