#pragma once

#include <string>

namespace fooball {

/// `value` as the shortest text that reads back to the same double ("-1", "0.1", "1e+300",
/// "inf", "nan"), via std::to_chars. The one place numbers become exact text: scene files,
/// CSV columns, run specs and error messages quoting the user's numbers.
std::string exactNumberText(double value);

}  // namespace fooball
