#include "number_text.h"

#include <algorithm>
#include <array>
#include <cstdio>

namespace fooball::cli {

std::string readableText(double value, int significantDigits) {
  std::array<char, 64> buffer{};
  const int length = std::snprintf(buffer.data(), buffer.size(), "%.*g", significantDigits, value);
  // snprintf reports the untruncated length; keep what fits.
  return {buffer.data(), std::min(static_cast<std::size_t>(length), buffer.size() - 1)};
}

}  // namespace fooball::cli
