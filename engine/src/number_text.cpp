#include "fooball/number_text.h"

#include <array>
#include <charconv>

namespace fooball {

std::string exactNumberText(double value) {
  // 32 characters hold the longest shortest form of a double ("-2.2250738585072014e-308").
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

}  // namespace fooball
