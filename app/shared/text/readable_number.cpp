#include "readable_number.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace fooball::text {

namespace {

std::string printed(const char* format, int digits, double value) {
  std::array<char, 64> buffer{};
  const int length = std::snprintf(buffer.data(), buffer.size(), format, digits, value);
  // snprintf reports the untruncated length; keep what fits.
  return {buffer.data(), std::min(static_cast<std::size_t>(length), buffer.size() - 1)};
}

}  // namespace

std::string readableText(double value, int significantDigits) {
  return printed("%.*g", significantDigits, value);
}

std::string figureText(double value) {
  constexpr int kSignificantDigits = 4;
  constexpr int kExponentFormDigits = 3;
  if (!std::isfinite(value)) return std::string(kNoFigure);
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e5)) {
    return printed("%.*e", kExponentFormDigits - 1, value);
  }
  return readableText(value, kSignificantDigits);
}

}  // namespace fooball::text
