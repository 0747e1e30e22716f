#include "view/temperature_palette.h"

#include <QColor>
#include <algorithm>
#include <cmath>

namespace fooball::gui {

namespace {

struct Stop {
  double position;
  QRgb colour;
};

constexpr Stop kStops[] = {
    {0.00, 0x2f4bff}, {0.30, 0x22c4f0}, {0.60, 0xffe14d}, {0.80, 0xff7a1a}, {1.00, 0xff2020},
};

int mix(int from, int to, double t) {
  return static_cast<int>(std::lround(from + (to - from) * t));
}

}  // namespace

TemperaturePalette::TemperaturePalette() {
  for (std::size_t i = 0; i < table_.size(); ++i) {
    const double position = double(i) / double(table_.size() - 1);
    std::size_t upper = 1;
    while (upper + 1 < std::size(kStops) && kStops[upper].position < position)
      ++upper;
    const Stop& a = kStops[upper - 1];
    const Stop& b = kStops[upper];
    const double t = std::clamp((position - a.position) / (b.position - a.position), 0.0, 1.0);
    table_[i] =
        qRgb(mix(qRed(a.colour), qRed(b.colour), t), mix(qGreen(a.colour), qGreen(b.colour), t),
             mix(qBlue(a.colour), qBlue(b.colour), t));
  }
}

QRgb TemperaturePalette::colourAt(double fraction) const {
  if (!(fraction > 0.0)) return table_.front();
  const auto index = static_cast<std::size_t>(std::min(fraction, 1.0) * double(table_.size() - 1));
  return table_[index];
}

QLinearGradient TemperaturePalette::gradient(QPointF start, QPointF end) const {
  QLinearGradient gradient(start, end);
  for (const Stop& stop : kStops)
    gradient.setColorAt(stop.position, QColor::fromRgb(stop.colour));
  return gradient;
}

}  // namespace fooball::gui
