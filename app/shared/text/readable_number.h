#pragma once

#include <string>
#include <string_view>

/// Numbers as text for people: fooball-cli's tables and summaries and the app's readouts. (The
/// exact text that reads back to the same double, for files and specs, is exactNumberText in
/// fooball/number_text.h.)
namespace fooball::text {

/// What a readout shows where it has no figure (yet): an em dash.
inline constexpr std::string_view kNoFigure = "—";

/// `value` with `significantDigits` significant digits (%g), e.g. "0.0166667".
std::string readableText(double value, int significantDigits = 6);

/// A measured figure in a readout: four significant digits ("0.0123", "1234"), or three in
/// exponent form when very small or very large (below 1e-3 or from 1e5 on: "1.23e-05",
/// "2.50e+06"), so that a figure is never wider than eight characters and the compare readout's
/// five columns fit beside the settings in a 1000 px window; "—" for no value (NaN, infinity).
std::string figureText(double value);

}  // namespace fooball::text
