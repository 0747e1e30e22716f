#include "view/density_splat.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace fooball::gui {

// The sums have a border of one pixel all round, so a ball on the image's edge adds to its four
// pixels without a test each; what falls on the border is off the image and never shown.

int DensitySplat::rowsPerBand(int width) {
  const std::size_t rowBytes = (std::size_t(std::max(width, 0)) + 2) * sizeof(PixelSum);
  return int(std::max<std::size_t>(1, kBandBytes / rowBytes));
}

void DensitySplat::begin(QSize size) {
  if (size.width() == width_ && size.height() == height_) return;
  width_ = size.width();
  height_ = size.height();
  sums_.assign(std::size_t(width_ + 2) * std::size_t(height_ + 2), PixelSum{});
  const int rows = rowsPerBand(width_);
  sumsPerBand_ = std::size_t(rows) * std::size_t(width_ + 2);
  bands_.resize(std::size_t((height_ + 2 + rows - 1) / rows));
  for (auto& band : bands_)
    band.clear();
  added_ = false;
}

std::optional<DensitySplat::Spot> DensitySplat::spotOf(QPointF centre) const {
  // Image pixel (i, j) is bordered pixel (i + 1, j + 1), whose centre lies at image point
  // (i + 0.5, j + 0.5): the four centres around the ball's start at (u, v) truncated.
  const double u = centre.x() + 0.5;
  const double v = centre.y() + 0.5;
  if (!(u > 0.0 && u < width_ + 1.0 && v > 0.0 && v < height_ + 1.0)) return {};  // also NaN
  const auto column = std::size_t(u);
  const auto row = std::size_t(v);
  return Spot{row * (std::size_t(width_) + 2) + column, float(u - double(column)),
              float(v - double(row))};
}

void DensitySplat::add(QPointF centre, double radius, QRgb colour) {
  const std::optional<Spot> spot = spotOf(centre);
  if (!spot) return;
  bands_[spot->index / sumsPerBand_].push_back({std::uint32_t(spot->index), spot->right, spot->down,
                                                float(std::numbers::pi * radius * radius), colour});
  added_ = true;
}

void DensitySplat::addToSums(const FiledBall& ball) {
  const float coverage = ball.coverage;
  const float red = coverage * float(qRed(ball.colour));
  const float green = coverage * float(qGreen(ball.colour));
  const float blue = coverage * float(qBlue(ball.colour));
  const auto addTo = [&](PixelSum& sum, float weight) {
    sum.coverage += weight * coverage;
    sum.red += weight * red;
    sum.green += weight * green;
    sum.blue += weight * blue;
  };
  PixelSum* pixel = &sums_[ball.index];
  const std::size_t stride = std::size_t(width_) + 2;
  const float right = ball.right;
  const float down = ball.down;
  addTo(pixel[0], (1.0F - right) * (1.0F - down));
  addTo(pixel[1], right * (1.0F - down));
  addTo(pixel[stride], (1.0F - right) * down);
  addTo(pixel[stride + 1], right * down);
}

void DensitySplat::composeOnto(QImage& image) {
  if (!added_) return;
  added_ = false;
  // A band's balls touch its rows and the first row of the next band: two bands' sums at most.
  for (auto& band : bands_) {
    for (const FiledBall& ball : band)
      addToSums(ball);
    band.clear();
  }
  const std::size_t stride = std::size_t(width_) + 2;
  const auto channel = [](int shown, float keep, float added) {
    return std::min(255, int(float(shown) * keep + added + 0.5F));  // rounded: all ≥ 0
  };
  for (int y = 0; y < height_; ++y) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(y));
    PixelSum* sums = &sums_[std::size_t(y + 1) * stride + 1];
    for (int x = 0; x < width_; ++x) {
      PixelSum& sum = sums[x];
      if (sum.coverage <= 0.0F) continue;
      // Covered c < 1: what was there shows through 1 − c. Covered more: the balls' mean colour.
      const float keep = std::max(0.0F, 1.0F - sum.coverage);
      const float scale = 1.0F / std::max(1.0F, sum.coverage);
      const QRgb shown = row[x];
      row[x] = qRgb(channel(qRed(shown), keep, sum.red * scale),
                    channel(qGreen(shown), keep, sum.green * scale),
                    channel(qBlue(shown), keep, sum.blue * scale));
      sum = {};
    }
  }
  // What fell on the border is cleared too, so every sum is zero for the next frame.
  const auto clear = [&](std::size_t from, std::size_t count) {
    std::fill_n(sums_.begin() + std::ptrdiff_t(from), count, PixelSum{});
  };
  clear(0, stride);
  clear(std::size_t(height_ + 1) * stride, stride);
  for (int y = 1; y <= height_; ++y) {
    clear(std::size_t(y) * stride, 1);
    clear(std::size_t(y) * stride + stride - 1, 1);
  }
}

}  // namespace fooball::gui
