#pragma once

#include <string>

namespace fooball::cli {

/// The shortest text that reads back as exactly `value` (std::to_chars), e.g. "0.1", "1e-300".
/// For files other programs read: CSV columns, option defaults.
std::string roundTripText(double value);

/// `value` with `significantDigits` significant digits (%g), e.g. "0.0166667". For people.
std::string readableText(double value, int significantDigits = 6);

}  // namespace fooball::cli
