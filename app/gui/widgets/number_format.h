#pragma once

#include <QLocale>
#include <QString>
#include <cmath>
#include <cstdint>

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

/// A counter as the user's locale writes whole numbers: "2,515" (the Counters table and the
/// view's collision count say the same).
inline QString formatCount(std::uint64_t count) {
  return QLocale().toString(qulonglong(count));
}

}  // namespace fooball::gui
