#pragma once

#include <QLinearGradient>
#include <QRgb>
#include <array>

namespace fooball::gui {

/// Speed as temperature: cold blue through cyan and yellow to hot red, bright enough to read on
/// a black background. A 256-entry table, so colouring 100,000 balls costs a lookup each.
class TemperaturePalette {
 public:
  TemperaturePalette();

  /// `fraction` of the top speed, clamped to [0, 1].
  QRgb colourAt(double fraction) const;
  /// The same scale as a gradient from `start` (cold) to `end` (hot), for the legend.
  QLinearGradient gradient(QPointF start, QPointF end) const;

 private:
  std::array<QRgb, 256> table_{};
};

}  // namespace fooball::gui
