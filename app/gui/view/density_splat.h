#pragma once

#include <QImage>
#include <QPointF>
#include <QRgb>
#include <QSize>
#include <cstdint>
#include <optional>
#include <vector>

namespace fooball::gui {

/// Draws balls smaller than a pixel as a density image. Each ball adds its colour, weighted by
/// the share of a pixel its disc covers (π r², r in px), to the four pixels nearest its centre,
/// split bilinearly by where the centre lies between them. composeOnto() then lays the sums over
/// the image: a pixel whose summed coverage c is below 1 keeps 1 − c of what it showed, and a
/// fuller one shows the mean colour of its balls.
///
/// Over a few pixels this is the discs' exact coverage and colour (the test compares them block
/// by block), so a pixel's brightness reads as the area its balls cover.
///
/// The balls come in scene order and land on random pixels, 16 bytes of sums each: a box of
/// millions of pixels would make every add a cache miss, and one that the solver's threads,
/// streaming their own balls beside it, make slower still. So add() only files each ball under
/// the band of rows it lands in, and composeOnto() adds band after band, each band's sums small
/// enough to stay in the core's cache (docs/performance.md).
class DensitySplat {
 public:
  /// Balls of a smaller radius (px) are splatted: their disc is narrower than a pixel.
  static constexpr double kMaxRadius = 0.5;

  /// Starts a frame on an image of `size` pixels (the sums are zero: composeOnto() clears them).
  void begin(QSize size);
  /// One ball, centre in image pixels as in DiscRasterizer (pixel (i, j) covers
  /// [i, i+1] × [j, j+1]); balls outside the image, or not finite, add nothing.
  void add(QPointF centre, double radius, QRgb colour);
  /// Lays the balls added since begin() over `image` (of the size begun with, opaque 32-bit
  /// RGB32 or ARGB32_Premultiplied) and clears them for the next frame.
  void composeOnto(QImage& image);

  /// Rows of pixels per band, for an image `width` pixels wide: as many as keep a band's sums
  /// within kBandBytes, at least one.
  static int rowsPerBand(int width);
  /// Bytes of sums per band: well within the smallest L2 the app meets (512 KiB).
  static constexpr std::size_t kBandBytes = 256 * 1024;

 private:
  /// What the balls splatted onto one pixel add up to: coverage in pixels, colour channels as
  /// coverage × channel (0–255).
  struct PixelSum {
    float coverage = 0.0F;
    float red = 0.0F;
    float green = 0.0F;
    float blue = 0.0F;
  };

  /// Where a ball adds: the first of its four sums (the others are the next one and the two
  /// below), and how far its centre lies from that pixel's centre towards them (0–1).
  struct Spot {
    std::size_t index;
    float right;
    float down;
  };
  /// The spot of a ball at `centre`; none off the image.
  std::optional<Spot> spotOf(QPointF centre) const;

  /// A ball as add() files it, until composeOnto() adds it to the sums.
  struct FiledBall {
    std::uint32_t index;  ///< Spot::index
    float right;          ///< Spot::right
    float down;           ///< Spot::down
    float coverage;       ///< pixels, πr²
    QRgb colour;
  };
  void addToSums(const FiledBall& ball);

  /// Row by row, (width_ + 2) × (height_ + 2): the image's pixels with a border of one all round
  /// (density_splat.cpp); all zero between frames.
  std::vector<PixelSum> sums_;
  /// The balls added since begin(), by band of rows of the sums (their top-left pixel's row);
  /// in each, in the order added. Kept between frames, so a frame allocates nothing.
  std::vector<std::vector<FiledBall>> bands_;
  std::size_t sumsPerBand_ = 1;  ///< pixels of the sums per band (its rows × their width)
  int width_ = 0;
  int height_ = 0;
  bool added_ = false;  ///< any ball since begin(): composeOnto() has work
};

}  // namespace fooball::gui
