#include "run_palette.h"

#include <gtest/gtest.h>

#include <QColor>
#include <cmath>
#include <set>
#include <vector>

#include "fooball/run_group.h"
#include "registry.h"

namespace fooball::colours {
namespace {

double distance(const QColor& a, const QColor& b) {
  return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
}

// WCAG's relative luminance, for the contrast ratio against the near-black plot (and the black
// simulation view).
double luminance(const QColor& colour) {
  const auto linear = [](double channel) {
    return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(colour.redF()) + 0.7152 * linear(colour.greenF()) +
         0.0722 * linear(colour.blueF());
}

TEST(RunPalette, EightRunColoursAreDistinctAndReadableOnBlack) {
  const double black = luminance(QColor(0x05, 0x05, 0x07));
  for (int run = 0; run < int(RunGroup::kMaxRuns); ++run) {
    const QColor colour = runColour(run);
    EXPECT_GE((luminance(colour) + 0.05) / (black + 0.05), 4.5) << colour.name().toStdString();
    EXPECT_GE(distance(colour, neutralColour()), 80.0) << colour.name().toStdString();
    EXPECT_GE(colour.saturation(), 100) << colour.name().toStdString();  // not a grey
    for (int other = 0; other < run; ++other) {
      EXPECT_GE(distance(colour, runColour(other)), 80.0)
          << colour.name().toStdString() << " vs " << runColour(other).name().toStdString();
    }
  }
}

TEST(RunPalette, TheChaosBaselineIsAGreyNoRunHas) {
  EXPECT_EQ(neutralColour().saturation(), 0);
  for (int run = 0; run < colourCount(); ++run)
    EXPECT_NE(runColour(run), neutralColour()) << run;
}

// The bug this palette removed: the Tools charts had five colours, the last the "unknown" grey,
// so every backend from the fifth on (chipmunk, bullet, …) was drawn grey.
TEST(RunPalette, EveryRegisteredBackendHasItsOwnColourAndNoneIsTheUnknownGrey) {
  const auto backends = registeredBackends();
  EXPECT_GE(colourCount(), int(backends.size()));
  std::set<QRgb> seen;
  for (const BackendInfo& backend : backends) {
    const QColor colour = backendColour(backend.name);
    EXPECT_NE(colour, neutralColour()) << backend.name;
    EXPECT_GE(colour.saturation(), 100) << backend.name;
    EXPECT_TRUE(seen.insert(colour.rgb()).second) << backend.name << " shares its colour";
    for (const BackendInfo& other : backends) {
      if (other.name == backend.name) continue;
      // Measured: the first eight are 87 apart; up to sixteen colours keep 66 apart.
      EXPECT_GE(distance(colour, backendColour(other.name)), 60.0)
          << backend.name << " vs " << other.name;
    }
  }
  EXPECT_EQ(backendColour("no such backend"), neutralColour());
}

TEST(RunPalette, ABackendHasTheColourOfTheRunAtItsPlaceInTheRegistry) {
  // The default compare runs (elastic, then box2d) have their backends' colours in the Tools.
  const auto backends = registeredBackends();
  for (std::size_t index = 0; index < backends.size(); ++index)
    EXPECT_EQ(backendColour(backends[index].name), runColour(int(index))) << backends[index].name;
}

TEST(RunPalette, AGrownRegistryStillGetsDistinctReadableColours) {
  // Tomorrow's registry, three times today's: every colour apart from the others, from grey and
  // from white, and readable on the black plot. Measured: 24 colours keep at least 53 apart
  // (the first eight 87).
  const double black = luminance(QColor(0x05, 0x05, 0x07));
  const std::vector<QColor> colours = distinctColours(24);
  ASSERT_EQ(colours.size(), 24u);
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const QColor& colour = colours[i];
    EXPECT_GE((luminance(colour) + 0.05) / (black + 0.05), 4.5) << colour.name().toStdString();
    EXPECT_GE(distance(colour, neutralColour()), 40.0) << colour.name().toStdString();
    EXPECT_GE(distance(colour, QColor(0xf5, 0xf5, 0xf5)), 40.0) << colour.name().toStdString();
    for (std::size_t other = 0; other < i; ++other) {
      EXPECT_GE(distance(colour, colours[other]), 40.0)
          << i << " " << colour.name().toStdString() << " vs " << other;
    }
  }
  // The first eight are the run colours, so that a run and its backend can match.
  for (int run = 0; run < int(RunGroup::kMaxRuns); ++run)
    EXPECT_EQ(colours[std::size_t(run)], runColour(run));
}

TEST(RunPalette, RunColoursRepeatPastThePalette) {
  EXPECT_EQ(runColour(colourCount()), runColour(0));
  EXPECT_EQ(runColour(-1), runColour(colourCount() - 1));
}

}  // namespace
}  // namespace fooball::colours
