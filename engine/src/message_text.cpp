#include "message_text.h"

#include <array>
#include <charconv>
#include <cstdio>

namespace fooball {

std::string roundedNumberText(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::general, 3);
  return {buffer.data(), result.ptr};
}

namespace {

std::string escaped(std::string_view text, std::size_t maxBytes, bool escapeQuotes) {
  std::string printable;
  for (std::size_t i = 0; i < text.size() && i < maxBytes; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\\' || (escapeQuotes && byte == '"')) {
      printable += '\\';
      printable += static_cast<char>(byte);
    } else if (byte < 0x20 || byte >= 0x7f) {
      std::array<char, 5> code{};
      std::snprintf(code.data(), code.size(), "\\x%02x", byte);
      printable += code.data();
    } else {
      printable += static_cast<char>(byte);
    }
  }
  if (text.size() > maxBytes) printable += "...";
  return printable;
}

}  // namespace

std::string printableText(std::string_view text, std::size_t maxBytes) {
  return escaped(text, maxBytes, false);
}

std::string quotedText(std::string_view text) {
  constexpr std::size_t kMaxShownBytes = 40;
  return '"' + escaped(text, kMaxShownBytes, true) + '"';
}

std::string withSource(std::string_view source, std::string_view message) {
  std::string line(source);
  line += ": ";
  line += message;
  return line;
}

}  // namespace fooball
