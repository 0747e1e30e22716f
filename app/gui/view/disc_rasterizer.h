#pragma once

#include <QImage>
#include <QPointF>
#include <QRgb>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fooball::gui {

/// Draws antialiased discs and rings straight into an opaque 32-bit image
/// (QImage::Format_RGB32 or Format_ARGB32_Premultiplied, alpha 255). This is what makes 100,000
/// balls per frame affordable; a QPainter ellipse per ball costs tens of times more.
/// - Small shapes (radius ≤ kMaxSpriteRadius px) are blended from coverage masks cached per
///   radius (1/8 px steps) and sub-pixel position (1/4 px steps): one multiply per pixel.
/// - Larger ones are filled span by span: the inside of each row is a plain fill, only the
///   one-pixel rim computes its coverage from the distance to the centre.
/// Coordinates are image pixels; pixel (i, j) covers [i, i+1] × [j, j+1]. Keep one rasterizer
/// for many frames so the masks are reused.
class DiscRasterizer {
 public:
  static constexpr double kMaxSpriteRadius = 12.0;  // px

  /// Draws into `image` from now on; it must outlive the drawing calls.
  void setTarget(QImage& image);

  void fillDisc(QPointF centre, double radius, QRgb colour);
  /// A ring of `width` pixels lying just inside `radius`.
  void strokeCircle(QPointF centre, double radius, double width, QRgb colour);

 private:
  /// Coverage (0–255) of one shape on a square of side pixels around its centre.
  struct Sprite {
    int side = 0;
    std::vector<std::uint8_t> coverage;
    std::vector<std::uint8_t> rowStart;  ///< first covered column of each row
    std::vector<std::uint8_t> rowEnd;    ///< one past the last covered column
  };
  /// The mask of a disc (`width` 0) or ring; radius and width in 1/8 px steps.
  const Sprite& sprite(int radiusStep, int widthStep, int subpixel);
  static void render(Sprite& sprite, int radiusStep, int widthStep, int subpixel);
  void drawSprite(QPointF centre, double radius, double width, quint32 colour);
  void blit(const Sprite& sprite, int left, int top, quint32 colour);
  /// Calls drawRow(pixels, dy², left, right) for every image row the circle of radius `outer`
  /// (px) crosses, with the clipped pixel range its outline spans on that row.
  template <class DrawRow>
  void forEachRowOfCircle(QPointF centre, double outer, DrawRow drawRow) const;
  void fillLargeDisc(QPointF centre, double radius, quint32 colour);
  void strokeLargeCircle(QPointF centre, double radius, double width, quint32 colour);
  quint32* row(int y) const { return reinterpret_cast<quint32*>(bits_ + y * bytesPerLine_); }

  uchar* bits_ = nullptr;
  qsizetype bytesPerLine_ = 0;
  int width_ = 0;
  int height_ = 0;
  /// Disc masks by radius step and sub-pixel position, created when first needed.
  std::vector<Sprite> discs_;
  /// Ring masks keyed by radius step, width step and sub-pixel position.
  std::unordered_map<std::uint64_t, Sprite> rings_;
};

}  // namespace fooball::gui
