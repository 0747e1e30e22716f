#include "view/disc_rasterizer.h"

#include <gtest/gtest.h>

#include <QImage>
#include <cmath>
#include <numbers>

namespace fooball::gui {
namespace {

/// Summed coverage of the red channel, in pixels.
double coveredArea(const QImage& image) {
  double area = 0.0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x)
      area += qRed(image.pixel(x, y)) / 255.0;
  }
  return area;
}

/// A rasterizer drawing into `image` (kept alive for the statement it is used in).
DiscRasterizer& draw(QImage& image) {
  static DiscRasterizer rasterizer;
  rasterizer.setTarget(image);
  return rasterizer;
}

TEST(DiscRasterizer, FilledDiscCoversItsAreaAndStaysInsideItsCircle) {
  QImage image(64, 64, QImage::Format_RGB32);
  image.fill(Qt::black);
  draw(image).fillDisc({30.3, 31.7}, 12.0, 0xff0000);
  EXPECT_NEAR(coveredArea(image), std::numbers::pi * 144.0, 3.0);
  EXPECT_EQ(image.pixel(30, 31), qRgb(255, 0, 0));
  EXPECT_EQ(image.pixel(30, 31 - 14), qRgb(0, 0, 0));
  EXPECT_EQ(image.pixel(30 + 14, 31), qRgb(0, 0, 0));
}

TEST(DiscRasterizer, DiscsAreClippedAtTheImageEdges) {
  QImage image(16, 16, QImage::Format_RGB32);
  image.fill(Qt::black);
  DiscRasterizer rasterizer;
  rasterizer.setTarget(image);
  rasterizer.fillDisc({0.0, 0.0}, 6.0, 0x00ff00);
  rasterizer.fillDisc({100.0, -40.0}, 6.0, 0x00ff00);
  rasterizer.strokeCircle({16.0, 16.0}, 8.0, 1.5, 0x00ff00);
  EXPECT_EQ(image.pixel(0, 0), qRgb(0, 255, 0));
}

TEST(DiscRasterizer, RingLeavesItsInsideUntouched) {
  QImage image(64, 64, QImage::Format_RGB32);
  image.fill(Qt::black);
  draw(image).strokeCircle({32.0, 32.0}, 20.0, 2.0, 0xff0000);
  EXPECT_EQ(image.pixel(32, 32), qRgb(0, 0, 0));
  EXPECT_GT(qRed(image.pixel(32 + 19, 32)), 240);
  EXPECT_NEAR(coveredArea(image), std::numbers::pi * (400.0 - 324.0), 6.0);
}

TEST(DiscRasterizer, SmallDiscsFromMasksMatchTheDirectlyFilledOnes) {
  // Just under and just over the mask limit: both ways give the same coverage.
  for (const double radius :
       {DiscRasterizer::kMaxSpriteRadius - 0.01, DiscRasterizer::kMaxSpriteRadius + 0.01}) {
    QImage image(64, 64, QImage::Format_RGB32);
    image.fill(Qt::black);
    draw(image).fillDisc({32.3, 31.6}, radius, 0xff0000);
    EXPECT_NEAR(coveredArea(image), std::numbers::pi * radius * radius, 3.0) << radius;
  }
}

}  // namespace
}  // namespace fooball::gui
