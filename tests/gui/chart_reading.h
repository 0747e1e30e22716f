#pragma once

#include <gtest/gtest.h>

#include <QString>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fooball::gui::testing {

/// The power of ten an axis title names ("residual (10⁻¹⁵ J)", "residual / |E₀| (×10³)"), as a
/// factor: what the axis' numbers are multiplied by. 1 when it names none.
inline double titleFactor(const QString& title) {
  static const QString kDigits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
  const qsizetype at = title.indexOf(QStringLiteral("10"));
  if (at < 0) return 1.0;
  int exponent = 0;
  int sign = 1;
  bool anyDigit = false;
  for (qsizetype i = at + 2; i < title.size(); ++i) {
    if (title[i] == QChar(u'⁻') && !anyDigit) {
      sign = -1;
    } else if (const qsizetype digit = kDigits.indexOf(title[i]); digit >= 0) {
      exponent = 10 * exponent + int(digit);
      anyDigit = true;
    } else {
      break;
    }
  }
  return anyDigit ? std::pow(10.0, sign * exponent) : 1.0;
}

/// The values a user reads off a value axis: each tick label drawn (top to bottom) as a number,
/// times the power of ten its title names. Fails the test for a label that is not a number.
inline std::vector<double> tickValues(const QStringList& labels, const QString& title) {
  std::vector<double> values;
  for (const QString& label : labels) {
    bool number = false;
    const double value = label.toDouble(&number);
    EXPECT_TRUE(number) << "tick label '" << label.toStdString() << "' on " << title.toStdString();
    if (number) values.push_back(value * titleFactor(title));
  }
  return values;
}

/// What the tick labels of a value axis must tell a user about data from `low` to `high` (in
/// the data's units): the lowest label is at or below the data and the highest at or above it,
/// and they are of its order of magnitude: on a linear axis the largest label is at most ten
/// times the largest value (no axis to 1000 J for 5 J); on a log axis the end labels are within
/// one label step (a power of ten) of the data's ends. `what` names the chart in a failure.
inline void expectTicksReadTheData(const QStringList& labels, const QString& title, double low,
                                   double high, bool logarithmic, const std::string& what) {
  const std::vector<double> ticks = tickValues(labels, title);
  ASSERT_GE(ticks.size(), 2u) << what << ": " << labels.join(' ').toStdString();
  const auto [lowest, highest] = std::minmax_element(ticks.begin(), ticks.end());
  const std::string shown = what + ": labels " + labels.join(' ').toStdString() + " on '" +
                            title.toStdString() + "' for data " + std::to_string(low) + " … " +
                            std::to_string(high);
  // The two roundings of dividing by the title's power and multiplying back.
  const double slack = 4e-16 * std::max(std::abs(*lowest), std::abs(*highest));
  EXPECT_LE(*lowest, low + slack) << shown;
  EXPECT_GE(*highest, high - slack) << shown;
  if (logarithmic) {
    ASSERT_GT(*lowest, 0.0) << shown;
    const double step = std::pow(*highest / *lowest, 1.0 / double(ticks.size() - 1));
    EXPECT_GT(*lowest, low / step * (1.0 - 1e-12)) << shown;
    EXPECT_LT(*highest, high * step * (1.0 + 1e-12)) << shown;
  } else {
    const double largestValue = std::max(std::abs(low), std::abs(high));
    const double largestLabel = std::max(std::abs(*lowest), std::abs(*highest));
    EXPECT_LE(largestLabel, 10.0 * largestValue) << shown;
  }
}

}  // namespace fooball::gui::testing
