#pragma once

#include <gtest/gtest.h>

#include <QLabel>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QTextDocument>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "chart_panel.h"
#include "time_chart.h"

namespace fooball::gui::testing {

/// What a user reads off the chart panel, read back by the tests from ChartPanel's reading
/// interface (data(), chart(), chartShown(), runLegend()). A chart index is one of
/// ChartPanel::Chart; a run index a run's or ChartPanel::kBaselineRun; the views are as of the
/// last refresh.

inline bool validChart(int chart) {
  return chart >= 0 && chart < ChartPanel::kChartCount;
}

/// Points the view holds for run `runIndex` in chart `chart` (the largest count over that
/// run's shown curves).
inline int displayedPointCount(const ChartPanel& panel, int chart, int runIndex) {
  return validChart(chart) ? panel.chart(chart).pointCount(runIndex) : 0;
}

/// Samples stored for run `runIndex` (or the baseline while it is shown).
inline std::size_t storedSampleCount(const ChartPanel& panel, int runIndex) {
  const ChartData& data = panel.data();
  if (runIndex == ChartPanel::kBaselineRun) {
    return data.baselineShown() ? data.history(ChartData::kBaseline).storedCount() : 0;
  }
  if (runIndex < 0 || runIndex >= data.runCount()) return 0;
  return data.history(runIndex).storedCount();
}

/// The points a chart plots for a run, `curve` numbering the chart's quantities as in
/// ChartPanel::Chart; empty for a hidden chart or curve.
inline QList<QPointF> displayedPoints(const ChartPanel& panel, int chart, int runIndex,
                                      int curve = 0) {
  if (!panel.chartShown(chart)) return {};
  return panel.chart(chart).points(runIndex, curve);
}

inline QPen displayedPen(const ChartPanel& panel, int chart, int runIndex, int curve = 0) {
  return validChart(chart) ? panel.chart(chart).pen(runIndex, curve) : QPen(Qt::NoPen);
}

/// The value axis' range.
inline std::pair<double, double> displayedYRange(const ChartPanel& panel, int chart) {
  return validChart(chart) ? panel.chart(chart).valueRange() : std::pair{0.0, 0.0};
}

/// `chart`'s value axis title and tick labels as drawn (TimeChart::valueTickLabels).
inline QString displayedValueAxisTitle(const ChartPanel& panel, int chart) {
  return validChart(chart) ? panel.chart(chart).valueAxisTitle() : QString();
}

inline QStringList displayedValueTickLabels(const ChartPanel& panel, int chart) {
  return panel.chartShown(chart) ? panel.chart(chart).valueTickLabels() : QStringList();
}

inline bool chartShown(const ChartPanel& panel, int chart) {
  return panel.chartShown(chart);
}

/// The run legend above the charts, as plain text (empty when it is hidden: one run).
inline QString runLegendText(const ChartPanel& panel) {
  if (panel.runLegend().isHidden()) return {};
  QTextDocument document;
  document.setHtml(panel.runLegend().text());
  return document.toPlainText();
}

/// Markers held.
inline int markerCount(const ChartPanel& panel) {
  return static_cast<int>(panel.data().markers().size());
}

/// The markers' labels, oldest first.
inline QStringList markerLabels(const ChartPanel& panel) {
  QStringList labels;
  for (const ChartMarker& marker : panel.data().markers())
    labels.append(marker.label);
  return labels;
}

/// Markers inside the time axis's current range (drawn).
inline int displayedMarkerCount(const ChartPanel& panel) {
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    if (panel.chartShown(chart)) return panel.chart(chart).visibleMarkerCount();
  }
  return 0;
}

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
