#pragma once

#include <limits>
#include <optional>
#include <string>

namespace fooball::gui {

/// The lowest and highest finite value seen; empty until the first one.
struct ValueRange {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();

  bool empty() const { return low > high; }
  void include(double value) {
    if (value < low) low = value;
    if (value > high) high = value;
  }
  void include(const ValueRange& other) {
    if (other.empty()) return;
    include(other.low);
    include(other.high);
  }
};

/// An axis range with ticks at multiples of `tickInterval`.
struct AxisScale {
  double min = 0.0;
  double max = 1.0;
  double tickInterval = 0.2;
};

/// The smallest of 1, 2, 5 × 10ᵏ that is ≥ `roughStep` (> 0); 1 for anything else.
double niceStep(double roughStep);

/// A value axis holding `data` with a little padding, ends on round ticks, about `ticks`
/// intervals. Keeps `current` while the data fits in it and fills at least a third of it, so
/// the axis does not jitter as values wander; a range narrower than a millionth of the values'
/// magnitude is widened, so rounding noise in a conserved quantity draws as a flat line.
AxisScale followValues(const ValueRange& data, const std::optional<AxisScale>& current, int ticks);

/// A base-10 log axis from 10^lowExponent to 10^highExponent, labelled every `decadesPerTick`
/// decades (both ends are labelled: they are multiples of it).
struct LogAxisScale {
  int lowExponent = -12;
  int highExponent = 0;
  int decadesPerTick = 3;

  double min() const;
  double max() const;
};

/// A log value axis holding `data` (positive values: a log axis has no room for the rest) from
/// the power of ten at or below its lowest value to the one at or above its highest, at least a
/// decade, labelled every 1, 2, 3, … decades so that there are at most `ticks` intervals. Keeps
/// `current` while the data fits in it and it is at most three decades wider than needed, so a
/// divergence wandering within a decade does not rescale the axis on every redraw.
LogAxisScale followLogValues(const ValueRange& data, const std::optional<LogAxisScale>& current,
                             int ticks);

/// A time axis (s) from `start` that reaches at least `end` in whole ticks: as a run grows,
/// the axis grows in steps instead of rescaling on every refresh.
AxisScale growingTimeScale(double start, double end);

/// A time axis (s) `window` wide that ends at `end`, or starts at `start` until the run is
/// that long; ticks stay at round times while it scrolls.
AxisScale scrollingTimeScale(double start, double end, double window);

/// The power of ten the values of `scale` are drawn in, chosen so that every tick is a whole
/// number or a half: 0 while the ticks are such numbers below 10⁵ already (energies of 0, 5,
/// 10 J; momenta of −0.5, 0, 0.5 N·s), else the power of the tick interval, so ticks read 1, 2 or
/// 5 apart and the axis title names the power once ("residual (10⁻¹⁵ J)": ticks −20, −10, 0, 10).
/// Qt Charts cannot draw tiny values as they are: it treats ranges narrower than 1e-12 as empty
/// and compares ends with qFuzzyCompare(1 + a, 1 + b), so an axis for residuals near 1e-14 J kept
/// reading ±1 while the curve filled it. And it places ticks by adding the interval over and
/// over, so fractional ticks read "-8e-28" or "-0.0" for 0: whole numbers add exactly.
int displayExponent(const AxisScale& scale);

/// `scale` in units of 10^`exponent` (displayExponent): ends and interval are whole numbers, or
/// halves at exponent 0.
AxisScale inDisplayUnits(const AxisScale& scale, int exponent);

/// " (10⁻¹⁴ J)", " (J)", " (×10⁻¹⁵)" or "": what an axis title adds after its quantity's name for
/// values drawn in units of 10^`exponent` of `unit` ("" for a ratio). UTF-8.
std::string unitSuffix(const std::string& unit, int exponent);

/// printf-style label format for the ticks of a time axis `scale` (s, never negative): enough
/// digits to tell neighbouring ticks apart and no more; scientific notation for very large or
/// small magnitudes.
std::string tickLabelFormat(const AxisScale& scale);

}  // namespace fooball::gui
