#pragma once

#include <string>

namespace fooball::cli {

/// `value` with `significantDigits` significant digits (%g), e.g. "0.0166667". For people.
std::string readableText(double value, int significantDigits = 6);

}  // namespace fooball::cli
