#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "fooball/number_text.h"

namespace fooball {

/// `value` to three significant digits, for quantities the program derived ("0.0312", "12.5").
std::string roundedNumberText(double value);

/// `text` with backslashes and bytes outside printable ASCII escaped (\x89), and cut to
/// `maxBytes` with "...", so a message stays one readable line whatever the input held.
std::string printableText(std::string_view text, std::size_t maxBytes = 40);

/// printableText of the first 40 bytes in double quotes, inner quotes escaped: how messages
/// show the user's strings and keys.
std::string quotedText(std::string_view text);

/// "source: message": how every scene error names the file or preset it came from.
std::string withSource(std::string_view source, std::string_view message);

}  // namespace fooball
