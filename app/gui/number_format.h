#pragma once

#include <QString>
#include <cmath>

namespace fooball::gui {

/// About three significant digits without exponents for the range settings live in
/// (0.001 … 100,000): "9.81", "0.05", "250", "12,000".
inline QString formatNumber(double value) {
  const double magnitude = std::abs(value);
  if (magnitude == 0.0) return QStringLiteral("0");
  if (magnitude >= 100.0) return QString::number(std::round(value), 'f', 0);
  if (magnitude >= 10.0) return QString::number(value, 'f', 1);
  if (magnitude >= 1.0) return QString::number(value, 'f', 2);
  return QString::number(value, 'g', 3);
}

}  // namespace fooball::gui
