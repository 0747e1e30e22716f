#pragma once

#include <string>

/// Numbers as text for people: fooball-cli's tables and summaries and the app's readouts. (The
/// exact text that reads back to the same double, for files and specs, is exactNumberText in
/// fooball/number_text.h.)
namespace fooball::text {

/// `value` with `significantDigits` significant digits (%g), e.g. "0.0166667".
std::string readableText(double value, int significantDigits = 6);

/// A measured figure in a readout: four significant digits, in exponent form only when very small
/// or very large (below 1e-3 or from 1e5 on: "0.0123", "1234", "1.234e-05", "2.500e+06"), and
/// "—" for no value (NaN, infinity).
std::string figureText(double value);

}  // namespace fooball::text
