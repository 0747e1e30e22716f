#include "view/disc_rasterizer.h"

#include <algorithm>
#include <cmath>

namespace fooball::gui {

namespace {

constexpr int kRadiusSteps = 8;    // mask radii in 1/8 px
constexpr int kSubpixelSteps = 4;  // mask centres in 1/4 px

/// `colour` over `pixel` with coverage `alpha` in [0, 256], both opaque 0xffRRGGBB.
inline quint32 blend(quint32 pixel, quint32 colour, quint32 alpha) {
  const quint32 rest = 256 - alpha;
  const quint32 redBlue =
      (((colour & 0xff00ffu) * alpha + (pixel & 0xff00ffu) * rest) >> 8) & 0xff00ffu;
  const quint32 green =
      (((colour & 0x00ff00u) * alpha + (pixel & 0x00ff00u) * rest) >> 8) & 0x00ff00u;
  return 0xff000000u | redBlue | green;
}

inline void cover(quint32& pixel, quint32 colour, double coverage) {
  if (coverage <= 0.0) return;
  pixel = coverage >= 1.0 ? colour : blend(pixel, colour, static_cast<quint32>(coverage * 256.0));
}

/// Coverage of a pixel whose centre is `distance` px from the shape's centre: a disc of
/// `radius`, or with `width` > 0 a ring of that width just inside `radius`.
inline double coverageAt(double distance, double radius, double width) {
  const double outside = radius + 0.5 - distance;
  if (width <= 0.0) return outside;
  return std::min(outside, distance - (radius - width) + 0.5);
}

}  // namespace

void DiscRasterizer::setTarget(QImage& image) {
  bits_ = image.bits();
  bytesPerLine_ = image.bytesPerLine();
  width_ = image.width();
  height_ = image.height();
}

const DiscRasterizer::Sprite& DiscRasterizer::sprite(int radiusStep, int widthStep, int subpixel) {
  constexpr int kSubpixels = kSubpixelSteps * kSubpixelSteps;
  if (widthStep == 0) {
    const auto index = static_cast<std::size_t>(radiusStep * kSubpixels + subpixel);
    if (discs_.empty()) {
      discs_.resize(static_cast<std::size_t>((kMaxSpriteRadius * kRadiusSteps + 1) * kSubpixels));
    }
    Sprite& disc = discs_[index];
    if (disc.side == 0) render(disc, radiusStep, 0, subpixel);
    return disc;
  }
  const std::uint64_t key =
      (std::uint64_t(radiusStep) << 32) | (std::uint64_t(widthStep) << 8) | std::uint64_t(subpixel);
  Sprite& ring = rings_[key];
  if (ring.side == 0) render(ring, radiusStep, widthStep, subpixel);
  return ring;
}

void DiscRasterizer::render(Sprite& sprite, int radiusStep, int widthStep, int subpixel) {
  const double r = double(radiusStep) / kRadiusSteps;
  const double w = double(widthStep) / kRadiusSteps;
  // The centre lies in the middle pixel; coverage reaches r + 0.5 from it.
  const int half = static_cast<int>(std::ceil(r + 0.5));
  sprite.side = 2 * half + 1;
  const auto side = static_cast<std::size_t>(sprite.side);
  sprite.coverage.assign(side * side, 0);
  sprite.rowStart.assign(side, 0);
  sprite.rowEnd.assign(side, 0);
  const double cx = half + (subpixel % kSubpixelSteps + 0.5) / kSubpixelSteps;
  const double cy = half + (subpixel / kSubpixelSteps + 0.5) / kSubpixelSteps;
  for (std::size_t y = 0; y < side; ++y) {
    std::size_t first = side;
    std::size_t last = 0;
    for (std::size_t x = 0; x < side; ++x) {
      const double distance = std::hypot(double(x) + 0.5 - cx, double(y) + 0.5 - cy);
      const double coverage = std::clamp(coverageAt(distance, r, w), 0.0, 1.0);
      const auto alpha = static_cast<std::uint8_t>(std::lround(coverage * 255.0));
      sprite.coverage[y * side + x] = alpha;
      if (alpha > 0) {
        first = std::min(first, x);
        last = x + 1;
      }
    }
    sprite.rowStart[y] = static_cast<std::uint8_t>(std::min(first, last));
    sprite.rowEnd[y] = static_cast<std::uint8_t>(last);
  }
}

void DiscRasterizer::blit(const Sprite& sprite, int left, int top, quint32 colour) {
  const int y0 = std::max(0, -top);
  const int y1 = std::min(sprite.side, height_ - top);
  for (int y = y0; y < y1; ++y) {
    const int x0 = std::max<int>(sprite.rowStart[static_cast<std::size_t>(y)], -left);
    const int x1 = std::min<int>(sprite.rowEnd[static_cast<std::size_t>(y)], width_ - left);
    const std::uint8_t* coverage = sprite.coverage.data() + y * sprite.side;
    quint32* pixels = row(top + y) + left;
    for (int x = x0; x < x1; ++x) {
      const quint32 alpha = coverage[x];
      // 0–255 to 0–256, so full coverage is exact.
      pixels[x] = alpha == 255 ? colour : blend(pixels[x], colour, alpha + (alpha >> 7));
    }
  }
}

void DiscRasterizer::drawSprite(QPointF centre, double radius, double width, quint32 colour) {
  const double x = std::floor(centre.x());
  const double y = std::floor(centre.y());
  const double reach = kMaxSpriteRadius + 2.0;
  if (!(x > -reach && y > -reach && x < width_ + reach && y < height_ + reach)) return;
  const int subX =
      std::min(kSubpixelSteps - 1, static_cast<int>((centre.x() - x) * kSubpixelSteps));
  const int subY =
      std::min(kSubpixelSteps - 1, static_cast<int>((centre.y() - y) * kSubpixelSteps));
  const int radiusStep = static_cast<int>(std::lround(radius * kRadiusSteps));
  const int widthStep =
      width > 0.0 ? std::max(1, static_cast<int>(std::lround(width * kRadiusSteps))) : 0;
  const Sprite& mask = sprite(radiusStep, widthStep, subY * kSubpixelSteps + subX);
  const int half = mask.side / 2;
  blit(mask, static_cast<int>(x) - half, static_cast<int>(y) - half, colour);
}

void DiscRasterizer::fillDisc(QPointF centre, double radius, QRgb colour) {
  colour |= 0xff000000u;
  if (radius > kMaxSpriteRadius) {
    fillLargeDisc(centre, radius, colour);
  } else {
    drawSprite(centre, radius, 0.0, colour);
  }
}

void DiscRasterizer::strokeCircle(QPointF centre, double radius, double width, QRgb colour) {
  colour |= 0xff000000u;
  if (radius > kMaxSpriteRadius) {
    strokeLargeCircle(centre, radius, width, colour);
  } else {
    drawSprite(centre, radius, width, colour);
  }
}

template <class DrawRow>
void DiscRasterizer::forEachRowOfCircle(QPointF centre, double outer, DrawRow drawRow) const {
  const double cx = centre.x();
  const double cy = centre.y();
  const int top = std::max(0, static_cast<int>(std::floor(cy - outer)));
  const int bottom = std::min(height_ - 1, static_cast<int>(std::floor(cy + outer)));
  for (int y = top; y <= bottom; ++y) {
    const double dy = y + 0.5 - cy;
    const double dy2 = dy * dy;
    if (dy2 >= outer * outer) continue;
    const double outerHalf = std::sqrt(outer * outer - dy2);
    const int left = std::max(0, static_cast<int>(std::floor(cx - outerHalf)));
    const int right = std::min(width_ - 1, static_cast<int>(std::floor(cx + outerHalf)));
    drawRow(row(y), dy2, left, right);
  }
}

void DiscRasterizer::fillLargeDisc(QPointF centre, double radius, quint32 colour) {
  const double cx = centre.x();
  const double outer = radius + 0.5;  // beyond this a pixel centre gets no coverage
  const double inner = radius - 0.5;  // within this a pixel is fully covered
  forEachRowOfCircle(centre, outer, [&](quint32* pixels, double dy2, int left, int right) {
    // Pixels whose centres lie within the inner circle: [fullLeft, fullRight].
    int fullLeft = right + 1;
    int fullRight = right;
    if (dy2 < inner * inner) {
      const double innerHalf = std::sqrt(inner * inner - dy2);
      const int first = std::max(left, static_cast<int>(std::ceil(cx - innerHalf - 0.5)));
      const int last = std::min(right, static_cast<int>(std::floor(cx + innerHalf - 0.5)));
      if (first <= last) {
        fullLeft = first;
        fullRight = last;
      }
    }
    const auto rim = [&](int x) {
      const double dx = x + 0.5 - cx;
      cover(pixels[x], colour, outer - std::sqrt(dx * dx + dy2));
    };
    for (int x = left; x < fullLeft; ++x)
      rim(x);
    std::fill(pixels + fullLeft, pixels + fullRight + 1, colour);
    for (int x = fullRight + 1; x <= right; ++x)
      rim(x);
  });
}

void DiscRasterizer::strokeLargeCircle(QPointF centre, double radius, double width,
                                       quint32 colour) {
  const double cx = centre.x();
  const double outer = radius + 0.5;
  const double hole = radius - width - 0.5;  // within this a pixel gets no coverage
  forEachRowOfCircle(centre, outer, [&](quint32* pixels, double dy2, int left, int right) {
    int holeLeft = right + 1;
    int holeRight = right;
    if (hole > 0.0 && dy2 < hole * hole) {
      const double holeHalf = std::sqrt(hole * hole - dy2);
      holeLeft = static_cast<int>(std::ceil(cx - holeHalf - 0.5));
      holeRight = static_cast<int>(std::floor(cx + holeHalf - 0.5));
    }
    for (int x = left; x <= right; ++x) {
      if (x >= holeLeft && x <= holeRight) {
        x = holeRight;
        continue;
      }
      const double dx = x + 0.5 - cx;
      cover(pixels[x], colour, coverageAt(std::sqrt(dx * dx + dy2), radius, width));
    }
  });
}

}  // namespace fooball::gui
