#include "number_text.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>

namespace fooball::cli {

std::string roundTripText(double value) {
  // 32 characters hold the longest shortest form of a double ("-2.2250738585072014e-308").
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

std::string readableText(double value, int significantDigits) {
  std::array<char, 64> buffer{};
  const int length = std::snprintf(buffer.data(), buffer.size(), "%.*g", significantDigits, value);
  // snprintf reports the untruncated length; keep what fits.
  return {buffer.data(), std::min(static_cast<std::size_t>(length), buffer.size() - 1)};
}

}  // namespace fooball::cli
