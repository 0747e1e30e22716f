#include "axis_scale.h"

#include <algorithm>
#include <cmath>

namespace fooball::gui {
namespace {

/// Rough tick interval count of a time axis.
constexpr double kTimeTicks = 5.0;
/// Fraction of the data's span left free above and below it.
constexpr double kPadding = 0.08;
/// A kept axis must still show the data at least this large, or it is rescaled to fit.
constexpr double kMinFilledFraction = 1.0 / 3.0;
/// Narrowest value range relative to the values' magnitude (see followValues).
constexpr double kMinRelativeSpan = 1e-6;

AxisScale roundedOut(double low, double high, int ticks) {
  const double step = niceStep((high - low) / std::max(ticks, 1));
  return {std::floor(low / step) * step, std::ceil(high / step) * step, step};
}

}  // namespace

double niceStep(double roughStep) {
  if (!(roughStep > 0.0) || !std::isfinite(roughStep)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(roughStep)));
  for (const double multiple : {1.0, 2.0, 5.0}) {
    // The tolerance keeps an exact 1-2-5 step (0.2 may read as 0.2000000001) from rounding up.
    if (roughStep <= multiple * decade * (1.0 + 1e-9)) return multiple * decade;
  }
  return 10.0 * decade;
}

AxisScale followValues(const ValueRange& data, const std::optional<AxisScale>& current, int ticks) {
  if (data.empty()) return current.value_or(AxisScale{});
  if (current) {
    const double currentSpan = current->max - current->min;
    const bool fits = data.low >= current->min && data.high <= current->max;
    if (fits && data.high - data.low >= kMinFilledFraction * currentSpan) return *current;
  }
  const double magnitude = std::max(std::abs(data.low), std::abs(data.high));
  const double minSpan = magnitude > 0.0 ? kMinRelativeSpan * magnitude : 1.0;
  const double span = std::max(data.high - data.low, minSpan);
  const double middle = 0.5 * (data.low + data.high);
  const double halfPadded = 0.5 * span * (1.0 + 2.0 * kPadding);
  // Padding does not cross zero: values that cannot be negative (energies, |p|) keep 0 as the
  // axis's end instead of a tick of negative values. All-zero data stays centred.
  double low = middle - halfPadded;
  double high = middle + halfPadded;
  if (data.low >= 0.0 && data.high > 0.0) low = std::max(low, 0.0);
  if (data.high <= 0.0 && data.low < 0.0) high = std::min(high, 0.0);
  return roundedOut(low, high, ticks);
}

double LogAxisScale::min() const {
  return std::pow(10.0, lowExponent);
}

double LogAxisScale::max() const {
  return std::pow(10.0, highExponent);
}

LogAxisScale followLogValues(const ValueRange& data, const std::optional<LogAxisScale>& current,
                             int ticks) {
  if (data.empty() || !(data.low > 0.0)) return current.value_or(LogAxisScale{});
  // The decade exponents of doubles are within ±324, so these ints do not overflow.
  int low = static_cast<int>(std::floor(std::log10(data.low)));
  int high = static_cast<int>(std::ceil(std::log10(data.high)));
  if (high <= low) high = low + 1;
  const int decadesPerTick =
      std::max(1, (high - low + std::max(ticks, 1) - 1) / std::max(ticks, 1));
  // Both ends on a labelled decade: round outwards to multiples of decadesPerTick.
  const auto floorToMultiple = [decadesPerTick](int exponent) {
    const int remainder = ((exponent % decadesPerTick) + decadesPerTick) % decadesPerTick;
    return exponent - remainder;
  };
  low = floorToMultiple(low);
  high = -floorToMultiple(-high);
  const LogAxisScale fresh{low, high, decadesPerTick};
  if (current) {
    const bool fits = data.low >= current->min() && data.high <= current->max();
    const int extraDecades =
        (current->highExponent - current->lowExponent) - (fresh.highExponent - fresh.lowExponent);
    if (fits && extraDecades <= 3) return *current;
  }
  return fresh;
}

AxisScale growingTimeScale(double start, double end) {
  // 1 s at least: a run's first second grows into the axis instead of rescaling it each frame.
  const double span = std::max(end - start, 1.0);
  const double step = niceStep(span / kTimeTicks);
  return {start, start + std::ceil(span / step) * step, step};
}

AxisScale scrollingTimeScale(double start, double end, double window) {
  const double axisEnd = std::max(end, start + window);
  return {axisEnd - window, axisEnd, niceStep(window / kTimeTicks)};
}

int displayExponent(const AxisScale& scale) {
  const double magnitude = std::max(std::abs(scale.min), std::abs(scale.max));
  if (!(scale.tickInterval > 0.0) || !std::isfinite(scale.tickInterval)) return 0;
  // Halves add exactly too: 0.5 apart reads better than 5 apart in tenths.
  if (scale.tickInterval >= 0.5 && magnitude < 1e5) return 0;
  // The nudge keeps log10(1e-15) = −14.9999… from giving 10⁻¹⁵ steps of 10 × 10⁻¹⁶.
  return static_cast<int>(std::floor(std::log10(scale.tickInterval) + 1e-9));
}

AxisScale inDisplayUnits(const AxisScale& scale, int exponent) {
  if (exponent == 0) return scale;
  // Multiples of the interval by construction (followValues rounds its ends out to ticks): in
  // these units whole numbers up to rounding, which goes.
  const double unit = std::pow(10.0, exponent);
  return {std::round(scale.min / unit), std::round(scale.max / unit),
          std::round(scale.tickInterval / unit)};
}

std::string unitSuffix(const std::string& unit, int exponent) {
  std::string power;
  if (exponent != 0) {
    static constexpr const char* kSuperscriptDigits[] = {"⁰", "¹", "²", "³", "⁴",
                                                         "⁵", "⁶", "⁷", "⁸", "⁹"};
    power = "10";
    if (exponent < 0) power += "⁻";
    for (const char digit : std::to_string(std::abs(exponent)))
      power += kSuperscriptDigits[digit - '0'];
  }
  if (unit.empty()) return power.empty() ? "" : " (×" + power + ")";
  return " (" + (power.empty() ? unit : power + " " + unit) + ")";
}

std::string tickLabelFormat(const AxisScale& scale) {
  const double magnitude = std::max(std::abs(scale.min), std::abs(scale.max));
  // The nudge keeps log10(0.001) = −2.9999… from asking for a needless extra digit.
  const int stepExponent = static_cast<int>(std::floor(std::log10(scale.tickInterval) + 1e-9));
  if (magnitude >= 1e-3 && magnitude < 1e6) {
    return "%." + std::to_string(std::max(0, -stepExponent)) + "f";
  }
  const int magnitudeExponent = static_cast<int>(std::floor(std::log10(magnitude)));
  return "%." + std::to_string(std::clamp(magnitudeExponent - stepExponent + 1, 1, 15)) + "g";
}

}  // namespace fooball::gui
