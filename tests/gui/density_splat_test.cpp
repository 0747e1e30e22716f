// Balls narrower than a pixel are drawn as density (DensitySplat): each shows its disc's area
// and colour where its centre is, as antialiased discs would, and the view picks this by itself.

#include "view/density_splat.h"

#include <QImage>
#include <cmath>
#include <numbers>
#include <vector>

#include "fooball/split_mix64.h"
#include "gui_fixture.h"

namespace fooball::gui::testing {
namespace {

constexpr QRgb kWhite = 0xffffffff;

QImage blackImage(int width, int height) {
  QImage image(width, height, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::black);
  return image;
}

/// Summed red channel over [left, left+side) × [top, top+side), in pixels of full coverage.
double redArea(const QImage& image, int left, int top, int side) {
  double area = 0.0;
  for (int y = top; y < top + side; ++y) {
    for (int x = left; x < left + side; ++x)
      area += qRed(image.pixel(x, y)) / 255.0;
  }
  return area;
}

double discArea(double radius) {
  return std::numbers::pi * radius * radius;
}

TEST(DensitySplat, ABallOnAPixelCentreColoursThatPixelByItsArea) {
  QImage image = blackImage(16, 16);
  DensitySplat splat;
  splat.begin(image.size());
  splat.add({5.5, 7.5}, 0.4, 0xff0080ff);
  splat.composeOnto(image);
  const double coverage = discArea(0.4);  // 0.503 of the pixel
  EXPECT_EQ(image.pixel(5, 7),
            qRgb(0, int(std::lround(128 * coverage)), int(std::lround(255 * coverage))));
  EXPECT_EQ(redArea(image, 0, 0, 16), 0.0);
  EXPECT_EQ(image.pixel(4, 7), qRgb(0, 0, 0));
  EXPECT_EQ(image.pixel(5, 8), qRgb(0, 0, 0));
}

TEST(DensitySplat, ABallBetweenPixelCentresIsSharedByDistance) {
  QImage image = blackImage(16, 16);
  DensitySplat splat;
  splat.begin(image.size());
  // A quarter of the way from the centre of (5, 7) to that of (6, 7), level with both.
  splat.add({5.75, 7.5}, 0.45, kWhite);
  splat.composeOnto(image);
  const double coverage = discArea(0.45);
  EXPECT_EQ(qRed(image.pixel(5, 7)), std::lround(255 * 0.75 * coverage));
  EXPECT_EQ(qRed(image.pixel(6, 7)), std::lround(255 * 0.25 * coverage));
  EXPECT_NEAR(redArea(image, 0, 0, 16), coverage, 2 * 0.5 / 255) << "no more, no less";
}

TEST(DensitySplat, WhatWasDrawnShowsThroughWhatTheBallsDoNotCover) {
  QImage image(8, 8, QImage::Format_ARGB32_Premultiplied);
  image.fill(qRgb(100, 100, 100));
  DensitySplat splat;
  splat.begin(image.size());
  splat.add({3.5, 3.5}, 0.3, kWhite);
  splat.composeOnto(image);
  const double coverage = discArea(0.3);
  EXPECT_EQ(qRed(image.pixel(3, 3)), std::lround(100 * (1 - coverage) + 255 * coverage));
  EXPECT_EQ(image.pixel(2, 3), qRgb(100, 100, 100));
}

TEST(DensitySplat, ACrowdedPixelShowsItsBallsMeanColourAndHidesTheBackground) {
  QImage image(8, 8, QImage::Format_ARGB32_Premultiplied);
  image.fill(qRgb(0, 255, 0));
  DensitySplat splat;
  splat.begin(image.size());
  // Six balls of 0.4 px: three pixels' worth of discs on one pixel, half red, half blue.
  for (int k = 0; k < 3; ++k) {
    splat.add({2.5, 2.5}, 0.4, 0xffff0000);
    splat.add({2.5, 2.5}, 0.4, 0xff0000ff);
  }
  splat.composeOnto(image);
  EXPECT_EQ(image.pixel(2, 2), qRgb(128, 0, 128));
}

TEST(DensitySplat, BallsOffTheImageOrNotFiniteAddNothingAndEveryFrameStartsClear) {
  QImage image = blackImage(8, 8);
  DensitySplat splat;
  splat.begin(image.size());
  splat.add({-3.0, 4.0}, 0.4, kWhite);
  splat.add({4.0, 8.6}, 0.4, kWhite);
  splat.add({std::nan(""), 4.0}, 0.4, kWhite);
  splat.add({4.0, INFINITY}, 0.4, kWhite);
  splat.composeOnto(image);
  EXPECT_EQ(redArea(image, 0, 0, 8), 0.0);
  // A ball on the corner pixel's centre, then a frame with none: nothing is left over.
  splat.add({0.5, 0.5}, 0.4, kWhite);
  splat.composeOnto(image);
  EXPECT_GT(qRed(image.pixel(0, 0)), 0);
  image.fill(Qt::black);
  splat.begin(image.size());
  splat.composeOnto(image);
  EXPECT_EQ(redArea(image, 0, 0, 8), 0.0);
}

TEST(DensitySplat, BallsOnEveryRowOfAManyBandImageShowTheirSharesWhereTheyLie) {
  // add() files balls by band of rows and composeOnto() adds band by band: one ball a row,
  // each with pixels below it, so every band's edge has a ball whose lower pixels lie in the
  // next band. Each must show its bilinear shares on its own four pixels, and nothing else.
  constexpr int kWidth = 2048;
  constexpr int kHeight = 48;
  ASSERT_LE(DensitySplat::rowsPerBand(kWidth), kHeight / 4) << "the image spans several bands";
  QImage image = blackImage(kWidth, kHeight);
  DensitySplat splat;
  splat.begin(image.size());
  constexpr double kRadius = 0.45;
  for (int row = 0; row + 1 < kHeight; ++row) {
    // A quarter of a pixel right of and below the centre of (40·row + 10, row).
    splat.add({40.0 * row + 10.75, row + 0.75}, kRadius, kWhite);
  }
  splat.composeOnto(image);
  const double coverage = discArea(kRadius);
  for (int row = 0; row + 1 < kHeight; ++row) {
    const int left = 40 * row + 10;
    EXPECT_EQ(qRed(image.pixel(left, row)), std::lround(255 * 0.5625 * coverage)) << row;
    EXPECT_EQ(qRed(image.pixel(left + 1, row)), std::lround(255 * 0.1875 * coverage)) << row;
    EXPECT_EQ(qRed(image.pixel(left, row + 1)), std::lround(255 * 0.1875 * coverage)) << row;
    EXPECT_EQ(qRed(image.pixel(left + 1, row + 1)), std::lround(255 * 0.0625 * coverage)) << row;
  }
  double area = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x)
      area += qRed(image.pixel(x, y)) / 255.0;
  }
  EXPECT_NEAR(area, (kHeight - 1) * coverage, (kHeight - 1) * 4 * 0.5 / 255) << "no more, no less";
}

/// Adds the disc's exact coverage of each pixel, sampled on a 16 × 16 grid per pixel, to
/// `coverage` (side × side pixels, row by row).
void addSampledDisc(std::vector<double>& coverage, int side, QPointF centre, double radius) {
  constexpr int kSamples = 16;
  for (int y = int(centre.y() - radius); y <= int(centre.y() + radius); ++y) {
    for (int x = int(centre.x() - radius); x <= int(centre.x() + radius); ++x) {
      int inside = 0;
      for (int j = 0; j < kSamples; ++j) {
        for (int i = 0; i < kSamples; ++i) {
          const double dx = x + (i + 0.5) / kSamples - centre.x();
          const double dy = y + (j + 0.5) / kSamples - centre.y();
          inside += dx * dx + dy * dy < radius * radius;
        }
      }
      coverage[std::size_t(y * side + x)] += double(inside) / (kSamples * kSamples);
    }
  }
}

TEST(DensitySplat, ShowsTheDiscsExactCoverageBlockByBlock) {
  // 3,000 balls of 0.1–0.5 px at random in 128 × 128 px: 4% covered, so they seldom meet, and
  // no pixel is covered more than once over. Every 8 × 8 block shows the area the discs cover
  // in it. They differ only at the blocks' edges, where a disc spreads over a pixel's width and
  // a splat over the four pixels around its centre: a few hundredths of a pixel per ball there.
  constexpr int kSide = 128;
  constexpr int kBlock = 8;
  QImage image = blackImage(kSide, kSide);
  std::vector<double> exact(kSide * kSide, 0.0);
  DensitySplat splat;
  splat.begin(image.size());
  SplitMix64 random(11);
  double area = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const QPointF centre(random.between(2.0, kSide - 2.0), random.between(2.0, kSide - 2.0));
    const double radius = random.between(0.1, DensitySplat::kMaxRadius);
    splat.add(centre, radius, kWhite);
    addSampledDisc(exact, kSide, centre, radius);
    area += discArea(radius);
  }
  splat.composeOnto(image);
  EXPECT_NEAR(redArea(image, 0, 0, kSide), area, 0.005 * area);
  for (int top = 0; top < kSide; top += kBlock) {
    for (int left = 0; left < kSide; left += kBlock) {
      double covered = 0.0;
      for (int y = top; y < top + kBlock; ++y) {
        for (int x = left; x < left + kBlock; ++x)
          covered += exact[std::size_t(y * kSide + x)];
      }
      EXPECT_NEAR(redArea(image, left, top, kBlock), covered, 0.1 + 0.1 * covered)
          << "block at " << left << ", " << top;
    }
  }
}

class SubPixelView : public GuiTest {
 protected:
  /// The view pixel that holds `point` (m): the one it lies in, not the nearest corner.
  QPoint pixelUnder(Vec2 point) const {
    const QPointF pixels = view()->transformForRun(0).toPixels(point);
    return {int(std::floor(pixels.x())), int(std::floor(pixels.y()))};
  }
};

TEST_F(SubPixelView, BallsNarrowerThanAPixelShowTheirAreaAndBiggerOnesAreDiscs) {
  // 2,000 white balls of 5 mm on a grid (about 0.3 px in a 1280 × 800 window), and one of 0.3 m.
  Scene scene = fooball::testing::emptyBox();
  for (int row = 0; row < 25; ++row) {
    for (int column = 0; column < 80; ++column)
      scene.balls.push_back(
          fooball::testing::ball({2.0 + 0.15 * column, 1.0 + 0.2 * row}, {0.0, 0.0}, 0.005));
  }
  scene.balls.push_back(fooball::testing::ball({8.0, 7.5}, {0.0, 0.0}, 0.3));
  open(scene);
  view()->repaint();
  const ViewTransform transform = view()->transformForRun(0);
  const double pixelRadius = 0.005 * transform.scale();
  ASSERT_LT(pixelRadius, DensitySplat::kMaxRadius) << "the test needs sub-pixel balls";
  ASSERT_GT(pixelRadius, 0.1);
  const QImage image = view()->grab().toImage();

  // The small balls' band, with a pixel of margin: it shows 2,000 discs' area, to the 8-bit
  // rounding of each pixel they touch (at most 4 each).
  const QPoint low = pixelOf({1.9, 0.9});
  const QPoint high = pixelOf({14.1, 5.9});
  double shown = 0.0;
  for (int y = high.y(); y <= low.y(); ++y) {
    for (int x = low.x(); x <= high.x(); ++x)
      shown += qRed(image.pixel(x, y)) / 255.0;
  }
  const double area = 2000 * discArea(pixelRadius);
  EXPECT_NEAR(shown, area, 2000 * 4 * 0.5 / 255);
  // Each small ball is where it is: the pixel under a centre is lit, one halfway between two
  // columns is dark.
  EXPECT_GT(qRed(image.pixel(pixelUnder({2.0, 1.0}))), 0);
  EXPECT_EQ(qRed(image.pixel(pixelUnder({2.075, 1.1}))), 0);
  // The big ball (~17 px) is a disc: solid white at its centre.
  EXPECT_EQ(image.pixel(pixelUnder({8.0, 7.5})), qRgb(255, 255, 255));
}

}  // namespace
}  // namespace fooball::gui::testing
