#include "chart_panel.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QFile>
#include <QImage>
#include <QLogValueAxis>
#include <QRegularExpression>
#include <QSplitterHandle>
#include <QTemporaryDir>
#include <QToolButton>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "axis_scale.h"
#include "chart_csv.h"
#include "chart_grid.h"
#include "chart_reading.h"
#include "chart_toolbar.h"
#include "run_palette.h"
#include "series_points.h"
#include "time_chart.h"

namespace fooball::gui {
namespace {

using testing::chartShown;
using testing::displayedMarkerCount;
using testing::displayedPen;
using testing::displayedPointCount;
using testing::displayedPoints;
using testing::displayedValueAxisTitle;
using testing::displayedValueTickLabels;
using testing::displayedYRange;
using testing::expectTicksReadTheData;
using testing::markerCount;
using testing::runLegendText;
using testing::storedSampleCount;
using testing::titleFactor;

constexpr int kMaxPoints = TimeChart::kMaxPointsPerCurve;

/// A plausible state at `time` (s): energy sloshing between kinetic and potential, momentum
/// turning, a residual that grows; `runIndex` shifts the numbers so runs differ.
Metrics metricsAt(double time, int runIndex = 0) {
  Metrics metrics;
  metrics.time = time;
  const double phase = time + runIndex;
  metrics.sums.kineticEnergy = 50.0 + 20.0 * std::sin(phase);
  metrics.sums.potentialEnergy = 30.0 - 20.0 * std::sin(phase);
  metrics.sums.momentum = {4.0 * std::cos(phase), 3.0 * std::sin(0.5 * phase)};
  metrics.energyResidual = (1.0 + runIndex) * 1e-6 * time;
  metrics.initialEnergy = 80.0;  // J, the total energy above at every time
  return metrics;
}

/// Run `runIndex`'s divergence from run 0 at `time` (s): none for run 0; for the others it grows
/// a decade every 2/3 s from k/3 · 1e-12 m, up to k/3 · 1e3 m at 10 s, and stays there.
Divergence divergenceAt(double time, int runIndex) {
  Divergence divergence;
  if (runIndex == 0) return divergence;
  const double scale = runIndex / 3.0;
  divergence.rmsPositionDifference = scale * 1e-12 * std::pow(10.0, 1.5 * std::min(time, 10.0));
  divergence.maxPositionDifference = 2.5 * divergence.rmsPositionDifference;
  divergence.energyDifference = 1e-3 * runIndex;
  divergence.momentumDifference = 1e-4 * runIndex;
  return divergence;
}

/// The chaos baseline: run 0's method, its own numbers (run "10"), a divergence from 1e-9 m.
Metrics baselineMetricsAt(double time) {
  return metricsAt(time, 10);
}
Divergence baselineDivergenceAt(double time) {
  Divergence divergence;
  divergence.rmsPositionDifference = 1e-9 * std::pow(10.0, 0.5 * time);
  divergence.maxPositionDifference = 3.0 * divergence.rmsPositionDifference;
  return divergence;
}

void addRun(ChartPanel& panel, int runIndex, int count, double dt, double start = 0.0) {
  for (int i = 0; i < count; ++i) {
    const double time = start + i * dt;
    panel.addSample(runIndex, metricsAt(time, runIndex), divergenceAt(time, runIndex));
  }
}

void addBaseline(ChartPanel& panel, int count, double dt) {
  for (int i = 0; i < count; ++i)
    panel.addBaselineSample(baselineMetricsAt(i * dt), baselineDivergenceAt(i * dt));
}

QAction* toggleNamed(ChartPanel& panel, const char* name) {
  auto* toggle = panel.findChild<QAction*>(name);
  EXPECT_NE(toggle, nullptr) << name;
  return toggle;
}

/// The lines of `path`, which must end with a line break.
QList<QByteArray> csvLines(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  QList<QByteArray> lines = file.readAll().split('\n');
  EXPECT_TRUE(lines.back().isEmpty());  // the last row ends its line too
  lines.removeLast();
  return lines;
}

/// The charts that draw every run (the divergence chart leaves run 0 out).
constexpr std::array kRunCharts{ChartPanel::kMomentumChart, ChartPanel::kEnergyChart,
                                ChartPanel::kResidualChart};

/// A panel on screen (offscreen) and wide enough for 2000 points per curve, as in a dock.
class ChartPanelTest : public ::testing::Test {
 protected:
  ChartPanelTest() {
    panel.resize(1400, 1000);
    panel.show();
    QApplication::processEvents();
  }

  ChartPanel panel;
};

/// Checks that every curve of run `run` plots, at its sample times (every `dt` from 0), the
/// metrics metricsAt(time, run) and divergenceAt(time, run) it was fed; `count` points each.
void expectRunPlotsItsMetrics(const ChartPanel& panel, int run, int count, double dt);

TEST_F(ChartPanelTest, CompareModeDrawsBothRunsInEveryChart) {
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);
  panel.refresh();
  expectRunPlotsItsMetrics(panel, 0, 600, 1.0 / 60.0);
  expectRunPlotsItsMetrics(panel, 1, 600, 1.0 / 60.0);
  EXPECT_TRUE(chartShown(panel, ChartPanel::kDivergenceChart));
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kDivergenceChart, 0), 0);  // no self-divergence
}

TEST_F(ChartPanelTest, SingleModeDrawsRunZeroOnly) {
  panel.reset({"elastic"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);    // no such run: ignored
  addBaseline(panel, 600, 1.0 / 60.0);  // no baseline shown: ignored
  panel.refresh();
  expectRunPlotsItsMetrics(panel, 0, 600, 1.0 / 60.0);
  for (const int chart : kRunCharts)
    EXPECT_EQ(displayedPointCount(panel, chart, 1), 0) << "chart " << chart;
  EXPECT_EQ(storedSampleCount(panel, 1), 0u);
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), 0u);
  // One run and no baseline: nothing diverges, so the divergence chart and the run legend step
  // aside.
  EXPECT_FALSE(chartShown(panel, ChartPanel::kDivergenceChart));
  EXPECT_TRUE(runLegendText(panel).isEmpty());
}

/// Checks that `points` are at the sample times of a run fed every `dt` from 0 and that each y,
/// times the axis' `factor` (titleFactor), is what `expected` says for that time: exactly when the
/// axis shows the values as they are, else to the two roundings of dividing and multiplying.
void expectPlotted(const QList<QPointF>& points, int count, double dt,
                   const std::function<double(double)>& expected, const std::string& what,
                   double factor = 1.0) {
  ASSERT_EQ(points.size(), count) << what;
  for (qsizetype i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].x(), static_cast<double>(i) * dt) << what << " point " << i;
    const double want = expected(points[i].x());
    if (factor == 1.0) {
      EXPECT_EQ(points[i].y(), want) << what << " at t = " << points[i].x();
    } else {
      EXPECT_NEAR(points[i].y() * factor, want, 4e-16 * std::abs(want))
          << what << " at t = " << points[i].x();
    }
  }
}

/// Four runs and the chaos baseline, as a compare session with the baseline on shows them.
class FourRunsAndBaseline : public ChartPanelTest {
 protected:
  static constexpr int kRuns = 4;
  static constexpr int kSamples = 600;
  static constexpr double kDt = 1.0 / 60.0;  // 10 s: inside the 20 s window

  FourRunsAndBaseline() {
    panel.reset({"elastic", "elastic:substeps=16", "exact", "box2d:substeps=8"});
    panel.setBaselineShown(true);
    for (int run = 0; run < kRuns; ++run)
      addRun(panel, run, kSamples, kDt);
    addBaseline(panel, kSamples, kDt);
    panel.refresh();
  }
};

void expectRunPlotsItsMetrics(const ChartPanel& panel, int run, int count, double dt) {
  const std::string name = "run " + std::to_string(run);
  const auto momentum = [run](double time) { return metricsAt(time, run).sums.momentum; };
  expectPlotted(
      displayedPoints(panel, ChartPanel::kMomentumChart, run, 0), count, dt,
      [&](double time) { return momentum(time).x; }, name + " px");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kMomentumChart, run, 1), count, dt,
      [&](double time) { return momentum(time).y; }, name + " py");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kMomentumChart, run, 2), count, dt,
      [&](double time) { return std::hypot(momentum(time).x, momentum(time).y); }, name + " |p|");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kEnergyChart, run, 0), count, dt,
      [run](double time) { return metricsAt(time, run).sums.kineticEnergy; }, name + " kinetic");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kEnergyChart, run, 1), count, dt,
      [run](double time) { return metricsAt(time, run).sums.potentialEnergy; },
      name + " potential");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kEnergyChart, run, 2), count, dt,
      [run](double time) { return metricsAt(time, run).sums.totalEnergy(); }, name + " total");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kResidualChart, run, 0), count, dt,
      [run](double time) { return metricsAt(time, run).energyResidual; }, name + " residual",
      titleFactor(displayedValueAxisTitle(panel, ChartPanel::kResidualChart)));
  if (run == 0) {
    EXPECT_TRUE(displayedPoints(panel, ChartPanel::kDivergenceChart, 0).isEmpty());
  } else {
    expectPlotted(
        displayedPoints(panel, ChartPanel::kDivergenceChart, run), count, dt,
        [run](double time) { return divergenceAt(time, run).rmsPositionDifference; },
        name + " divergence");
  }
}

TEST_F(FourRunsAndBaseline, EachRunPlotsTheMetricsItWasFed) {
  for (int run = 0; run < kRuns; ++run)
    expectRunPlotsItsMetrics(panel, run, kSamples, kDt);
}

TEST_F(FourRunsAndBaseline, EveryChartsTickLabelsBracketItsDataAtItsMagnitude) {
  QApplication::processEvents();  // Qt Charts lays out its labels then
  // The data fed, chart by chart: every run's quantities (the divergence chart: runs 1 to 3 and
  // the baseline), over the 10 s fed.
  std::array<std::pair<double, double>, ChartPanel::kChartCount> data;
  data.fill({HUGE_VAL, -HUGE_VAL});
  const auto include = [&](int chart, double value) {
    data[chart] = {std::min(data[chart].first, value), std::max(data[chart].second, value)};
  };
  for (int i = 0; i < kSamples; ++i) {
    const double time = i * kDt;
    for (int run = 0; run < kRuns; ++run) {
      const Metrics metrics = metricsAt(time, run);
      const Vec2 p = metrics.sums.momentum;
      for (const double value : {p.x, p.y, std::hypot(p.x, p.y)})
        include(ChartPanel::kMomentumChart, value);
      for (const double value :
           {metrics.sums.kineticEnergy, metrics.sums.potentialEnergy, metrics.sums.totalEnergy()})
        include(ChartPanel::kEnergyChart, value);
      include(ChartPanel::kResidualChart, metrics.energyResidual);
      if (run > 0)
        include(ChartPanel::kDivergenceChart, divergenceAt(time, run).rmsPositionDifference);
    }
    include(ChartPanel::kDivergenceChart, baselineDivergenceAt(time).rmsPositionDifference);
  }
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    expectTicksReadTheData(displayedValueTickLabels(panel, chart),
                           displayedValueAxisTitle(panel, chart), data[chart].first,
                           data[chart].second, chart == ChartPanel::kDivergenceChart,
                           "chart " + std::to_string(chart));
  }
}

/// A residual of `size` J (either sign), wandering between 0.2 and 1.8 × size as a method's error
/// does, with E₀ = 10 J for the relative view.
Metrics residualOfSize(double time, double size) {
  Metrics metrics = metricsAt(time);
  metrics.energyResidual = size * (1.0 + 0.8 * std::sin(3.0 * time));
  metrics.sums.kineticEnergy = 10.0;
  metrics.sums.potentialEnergy = 0.0;
  metrics.initialEnergy = 10.0;
  return metrics;
}

/// What a user reads off the residual chart: every plotted point times the power of ten in the
/// axis title is the residual it was fed, the axis (times the same power) holds the data snugly,
/// and its tick labels are whole numbers, 0 among them when the range spans it, never "-0".
void expectResidualChartReads(ChartPanel& panel, double size, int samples, double dt,
                              bool relative) {
  const std::string what = (relative ? "relative residual " : "residual ") + std::to_string(size);
  const auto expected = [&](double time) {
    const double residual = residualOfSize(time, size).energyResidual;
    return relative ? residual / 10.0 : residual;
  };
  const QString title = displayedValueAxisTitle(panel, ChartPanel::kResidualChart);
  const double factor = titleFactor(title);
  // The chart's curves: the residual, then the relative residual.
  expectPlotted(displayedPoints(panel, ChartPanel::kResidualChart, 0, relative ? 1 : 0), samples,
                dt, expected, what + " (" + title.toStdString() + ")", factor);
  double low = HUGE_VAL;
  double high = -HUGE_VAL;
  for (int i = 0; i < samples; ++i) {
    low = std::min(low, expected(i * dt));
    high = std::max(high, expected(i * dt));
  }
  const auto [axisMin, axisMax] = displayedYRange(panel, ChartPanel::kResidualChart);
  EXPECT_LE(axisMin * factor, low) << what;
  EXPECT_GE(axisMax * factor, high) << what;
  // Snug: the data fill a third of the axis at least, so no axis of ±1 J for 1e-14 J.
  EXPECT_GE(high - low, (axisMax - axisMin) * factor / 3.0)
      << what << " on " << axisMin << ".." << axisMax << " × " << factor;
  const QStringList labels = displayedValueTickLabels(panel, ChartPanel::kResidualChart);
  EXPECT_GE(labels.size(), 2) << what;
  expectTicksReadTheData(labels, title, low, high, false, what);
  // Whole numbers, or halves with one decimal; never "-0".
  const QRegularExpression wholeNumber(
      QStringLiteral("^-?[1-9][0-9]{0,4}$|^0$|^-?[0-9]{1,5}\\.[05]$"));
  for (const QString& label : labels)
    EXPECT_TRUE(wholeNumber.match(label).hasMatch())
        << what << ": label '" << label.toStdString() << "' on " << title.toStdString();
  for (const QString& label : labels)
    EXPECT_FALSE(label == QStringLiteral("-0.0")) << what;
  if (axisMin < 0.0 && axisMax > 0.0) {
    EXPECT_TRUE(labels.contains(QStringLiteral("0")) || labels.contains(QStringLiteral("0.0")))
        << what;
  }
}

TEST_F(ChartPanelTest, ResidualChartReadsTheTrueValuesFromTinyToHuge) {
  constexpr int kSamples = 300;
  constexpr double kDt = 1.0 / 60.0;
  for (const bool relative : {false, true}) {
    for (const double magnitude :
         {1e-16, 1e-14, 3e-12, 1e-9, 2e-6, 1e-3, 0.5, 1.0, 70.0, 1e3, 1e6}) {
      for (const double sign : {1.0, -1.0}) {
        panel.reset({"elastic"});
        toggleNamed(panel, "relativeResidualToggle")->setChecked(relative);
        for (int i = 0; i < kSamples; ++i)
          panel.addSample(0, residualOfSize(i * kDt, sign * magnitude), Divergence{});
        panel.refresh();
        QApplication::processEvents();  // Qt Charts lays out its labels and titles then
        expectResidualChartReads(panel, sign * magnitude, kSamples, kDt, relative);
      }
    }
  }
}

TEST_F(FourRunsAndBaseline, EachRunIsDrawnInItsColour) {
  for (int run = 0; run < kRuns; ++run) {
    for (const int chart : kRunCharts)
      EXPECT_EQ(displayedPen(panel, chart, run).color(), colours::runColour(run)) << chart;
    if (run > 0) {
      EXPECT_EQ(displayedPen(panel, ChartPanel::kDivergenceChart, run).color(),
                colours::runColour(run));
      EXPECT_EQ(displayedPen(panel, ChartPanel::kDivergenceChart, run).style(), Qt::SolidLine);
    }
  }
  EXPECT_EQ(displayedPen(panel, ChartPanel::kDivergenceChart, 0).style(), Qt::NoPen);
  // The run legend names every run, run 0 as the reference.
  const QString legend = runLegendText(panel);
  EXPECT_TRUE(legend.contains("elastic (reference)")) << legend.toStdString();
  for (const char* label : {"elastic:substeps=16", "exact", "box2d:substeps=8"})
    EXPECT_TRUE(legend.contains(label)) << label;
}

TEST_F(FourRunsAndBaseline, BaselineIsAGreyDashedDivergenceCurveOnly) {
  expectPlotted(
      displayedPoints(panel, ChartPanel::kDivergenceChart, ChartPanel::kBaselineRun), kSamples, kDt,
      [](double time) { return baselineDivergenceAt(time).rmsPositionDifference; }, "baseline");
  const QPen pen = displayedPen(panel, ChartPanel::kDivergenceChart, ChartPanel::kBaselineRun);
  EXPECT_EQ(pen.color(), colours::neutralColour());
  EXPECT_EQ(pen.style(), Qt::CustomDashLine);
  EXPECT_EQ(colours::neutralColour().saturation(), 0);  // grey
  for (const int chart : kRunCharts)
    EXPECT_EQ(displayedPointCount(panel, chart, ChartPanel::kBaselineRun), 0) << chart;
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), static_cast<std::size_t>(kSamples));
}

TEST_F(FourRunsAndBaseline, DivergenceAxisIsLogAndBracketsTheData) {
  // The fed divergences run from 1/3 · 1e-12 m (run 1 at t = 0) to 1e3 m (run 3 at 10 s).
  double lowest = HUGE_VAL;
  double highest = 0.0;
  for (const int run : {1, 2, 3, ChartPanel::kBaselineRun}) {
    for (const QPointF& point : displayedPoints(panel, ChartPanel::kDivergenceChart, run)) {
      lowest = std::min(lowest, point.y());
      highest = std::max(highest, point.y());
    }
  }
  ASSERT_LT(lowest, 1e-12);
  ASSERT_GT(highest, 1e2);
  const auto [axisMin, axisMax] = displayedYRange(panel, ChartPanel::kDivergenceChart);
  EXPECT_LE(axisMin, lowest);
  EXPECT_GE(axisMax, highest);
  // Snug: within a label step of the data (16 decades on a plot with room for four or five
  // labels: four decades at most), not a default range.
  EXPECT_GE(axisMin, lowest / 1e4);
  EXPECT_LE(axisMax, highest * 1e4);
  // And it is a log axis that shows them.
  const QList<TimeChart*> charts = panel.findChildren<TimeChart*>();
  const auto divergence = std::find_if(charts.begin(), charts.end(), [](const TimeChart* chart) {
    return chart->chart()->title().startsWith("Divergence");
  });
  ASSERT_NE(divergence, charts.end());
  const QList<QAbstractAxis*> valueAxes = (*divergence)->chart()->axes(Qt::Vertical);
  ASSERT_EQ(valueAxes.size(), 1);
  ASSERT_EQ(valueAxes[0]->type(), QAbstractAxis::AxisTypeLogValue);
  const auto* logAxis = static_cast<const QLogValueAxis*>(valueAxes[0]);
  EXPECT_EQ(logAxis->min(), axisMin);
  EXPECT_EQ(logAxis->max(), axisMax);
  // Labels at whole decades, a handful of them.
  const double decadesPerLabel = std::log10(logAxis->base());
  EXPECT_EQ(decadesPerLabel, std::round(decadesPerLabel));
  EXPECT_LE(std::log10(axisMax / axisMin) / decadesPerLabel, 6.0);
}

TEST_F(ChartPanelTest, DivergenceAxisSkipsValuesThatAreNotPositive) {
  panel.reset({"elastic", "exact"});
  // Right after a synchronise the runs are identical: a divergence of 0, which a log axis has
  // no place for. It is left out, and so is a (nonsensical) negative one.
  const std::array values{0.0, 1e-12, 1e-9, -1.0, 1e-6, 1e-3, 1.0, 1e3};
  for (std::size_t i = 0; i < values.size(); ++i) {
    Divergence divergence;
    divergence.rmsPositionDifference = values[i];
    const double time = 0.1 * static_cast<double>(i);
    panel.addSample(0, metricsAt(time), {});
    panel.addSample(1, metricsAt(time, 1), divergence);
  }
  panel.refresh();
  const QList<QPointF> points = displayedPoints(panel, ChartPanel::kDivergenceChart, 1);
  ASSERT_EQ(points.size(), 6);
  EXPECT_EQ(points.front().y(), 1e-12);
  EXPECT_EQ(points.back().y(), 1e3);
  const auto [axisMin, axisMax] = displayedYRange(panel, ChartPanel::kDivergenceChart);
  EXPECT_GT(axisMin, 0.0);
  EXPECT_LE(axisMin, 1e-12);
  EXPECT_GE(axisMax, 1e3);
  EXPECT_GE(axisMin, 1e-15);
  EXPECT_LE(axisMax, 1e6);
}

TEST_F(ChartPanelTest, DivergenceChartNeedsTwoRunsOrTheBaseline) {
  panel.reset({"elastic"});
  EXPECT_FALSE(chartShown(panel, ChartPanel::kDivergenceChart));
  panel.setBaselineShown(true);
  EXPECT_TRUE(chartShown(panel, ChartPanel::kDivergenceChart));
  panel.setBaselineShown(false);
  EXPECT_FALSE(chartShown(panel, ChartPanel::kDivergenceChart));
  panel.addRun("exact");
  EXPECT_TRUE(chartShown(panel, ChartPanel::kDivergenceChart));
  toggleNamed(panel, "divergenceToggle")->setChecked(false);
  EXPECT_FALSE(chartShown(panel, ChartPanel::kDivergenceChart));
  EXPECT_TRUE(chartShown(panel, ChartPanel::kEnergyChart));
  toggleNamed(panel, "divergenceToggle")->setChecked(true);
  panel.removeRun(1);
  EXPECT_FALSE(chartShown(panel, ChartPanel::kDivergenceChart));
}

TEST_F(ChartPanelTest, HidingTheBaselineDropsItsHistory) {
  panel.reset({"elastic", "exact"});
  panel.setBaselineShown(true);
  addBaseline(panel, 50, 0.01);
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), 50u);
  panel.setBaselineShown(false);
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), 0u);
  addBaseline(panel, 50, 0.01);  // ignored while hidden
  panel.setBaselineShown(true);
  panel.refresh();
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), 0u);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kDivergenceChart, ChartPanel::kBaselineRun), 0);
}

TEST_F(ChartPanelTest, AddingARunKeepsTheOthersHistory) {
  panel.reset({"elastic"});
  addRun(panel, 0, 300, 0.01);  // 0 … 2.99 s alone
  panel.addRun("exact");        // compare mode begins at 3 s
  EXPECT_EQ(panel.runCount(), 2);
  EXPECT_EQ(storedSampleCount(panel, 0), 300u);
  EXPECT_EQ(storedSampleCount(panel, 1), 0u);
  addRun(panel, 0, 100, 0.01, 3.0);
  addRun(panel, 1, 100, 0.01, 3.0);
  panel.addRun("box2d");
  addRun(panel, 2, 10, 0.01, 4.0);
  panel.refresh();
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), 400);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 1), 100);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 2), 10);
  // Run 0's curve still starts at t = 0 with the values it had then.
  const QList<QPointF> total = displayedPoints(panel, ChartPanel::kEnergyChart, 0, 2);
  ASSERT_FALSE(total.isEmpty());
  EXPECT_EQ(total.front(), QPointF(0.0, metricsAt(0.0).sums.totalEnergy()));
  EXPECT_EQ(displayedPen(panel, ChartPanel::kEnergyChart, 2, 2).color(), colours::runColour(2));
}

TEST_F(ChartPanelTest, RemovingARunShiftsTheLaterOnesDown) {
  panel.reset({"elastic", "exact", "box2d", "xpbd"});
  for (int run = 0; run < 4; ++run)
    addRun(panel, run, 10 * (run + 1), 0.01);
  panel.removeRun(1);
  panel.refresh();
  ASSERT_EQ(panel.runCount(), 3);
  EXPECT_EQ(storedSampleCount(panel, 0), 10u);
  EXPECT_EQ(storedSampleCount(panel, 1), 30u);  // box2d's
  EXPECT_EQ(storedSampleCount(panel, 2), 40u);  // xpbd's
  EXPECT_EQ(storedSampleCount(panel, 3), 0u);
  // The run now at index 1 plots what run 2 was fed, in the colour of index 1.
  expectPlotted(
      displayedPoints(panel, ChartPanel::kEnergyChart, 1, 2), 30, 0.01,
      [](double time) { return metricsAt(time, 2).sums.totalEnergy(); }, "box2d total");
  expectPlotted(
      displayedPoints(panel, ChartPanel::kDivergenceChart, 2), 40, 0.01,
      [](double time) { return divergenceAt(time, 3).rmsPositionDifference; }, "xpbd divergence");
  EXPECT_EQ(displayedPen(panel, ChartPanel::kEnergyChart, 1, 2).color(), colours::runColour(1));
  const QString legend = runLegendText(panel);
  EXPECT_FALSE(legend.contains("exact")) << legend.toStdString();
  EXPECT_LT(legend.indexOf("box2d"), legend.indexOf("xpbd"));

  // Removing run 0 makes the next the reference.
  panel.removeRun(0);
  EXPECT_EQ(storedSampleCount(panel, 0), 30u);
  EXPECT_TRUE(runLegendText(panel).contains("box2d (reference)"));
  panel.removeRun(1);
  panel.removeRun(0);  // the last run stays
  panel.removeRun(5);  // no such run
  EXPECT_EQ(panel.runCount(), 1);
  EXPECT_EQ(storedSampleCount(panel, 0), 30u);
}

TEST_F(ChartPanelTest, RenamingARunKeepsItsHistory) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.csv");
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 20, 0.01);
  addRun(panel, 1, 20, 0.01);
  panel.renameRun(1, "elastic:substeps=16");
  EXPECT_EQ(storedSampleCount(panel, 1), 20u);
  panel.refresh();
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 1), 20);
  EXPECT_TRUE(runLegendText(panel).contains("elastic:substeps=16"));
  EXPECT_FALSE(runLegendText(panel).contains("exact"));
  ASSERT_TRUE(panel.exportCsv(path));
  const QList<QByteArray> lines = csvLines(path);
  ASSERT_EQ(lines.size(), 41);
  EXPECT_TRUE(lines[21].startsWith("elastic:substeps=16,")) << lines[21].toStdString();
  EXPECT_TRUE(lines[40].startsWith("elastic:substeps=16,"));
}

TEST_F(ChartPanelTest, EightRunsAreTheMost) {
  QStringList labels;
  for (int run = 0; run < 9; ++run)
    labels.append(QStringLiteral("elastic:substeps=%1").arg(1 << run));
  panel.reset(labels);
  EXPECT_EQ(panel.runCount(), ChartPanel::kMaxRuns);
  EXPECT_EQ(ChartPanel::kMaxRuns, 8);
  panel.addRun("exact");  // a ninth: ignored
  EXPECT_EQ(panel.runCount(), 8);
  for (int run = 0; run < 9; ++run)
    addRun(panel, run, 100 + run, 0.01);
  panel.refresh();
  for (int run = 0; run < 8; ++run) {
    EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, run), 100 + run);
    EXPECT_EQ(displayedPointCount(panel, ChartPanel::kDivergenceChart, run),
              run == 0 ? 0 : 100 + run);
    EXPECT_EQ(displayedPen(panel, ChartPanel::kMomentumChart, run, 2).color(),
              colours::runColour(run));
    EXPECT_TRUE(runLegendText(panel).contains(labels[run] + (run == 0 ? " (" : "")));
  }
  EXPECT_EQ(storedSampleCount(panel, 8), 0u);
  EXPECT_FALSE(runLegendText(panel).contains(labels[8]));
}

TEST_F(ChartPanelTest, ViewWaitsForARefresh) {
  panel.reset({"elastic"});
  addRun(panel, 0, 100, 0.01);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), 0);
  EXPECT_EQ(storedSampleCount(panel, 0), 100u);
  panel.refresh();
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), 100);
}

TEST_F(ChartPanelTest, PointsStayBoundedForLongRuns) {
  panel.reset({"elastic", "exact"});
  // 10⁵ samples a millisecond apart: the 20 s window alone holds 20 000 of them.
  addRun(panel, 0, 100'000, 1e-3);
  addRun(panel, 1, 100'000, 1e-3);
  EXPECT_LE(storedSampleCount(panel, 0),
            SampleHistory::kDefaultWholeRunCapacity + SampleHistory::kDefaultRecentCapacity);
  for (const bool wholeRun : {false, true}) {
    panel.setShowWholeRun(wholeRun);
    panel.refresh();
    for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
      for (int run = chart == ChartPanel::kDivergenceChart ? 1 : 0; run < 2; ++run) {
        // Two points per pixel column of a plot a few hundred pixels wide (the panel's grid
        // has two columns), however many samples.
        EXPECT_GT(displayedPointCount(panel, chart, run), TimeChart::kMinPointsPerCurve);
        EXPECT_LE(displayedPointCount(panel, chart, run), kMaxPoints);
      }
    }
  }
}

TEST_F(ChartPanelTest, WholeRunShowsMoreThanTheWindow) {
  panel.reset({"elastic"});
  addRun(panel, 0, 6000, 1.0 / 60.0);  // 100 s
  panel.setWindowSeconds(20.0);
  panel.refresh();
  const int windowPoints = displayedPointCount(panel, ChartPanel::kEnergyChart, 0);
  EXPECT_NEAR(windowPoints, 20 * 60, 2);
  panel.setShowWholeRun(true);
  EXPECT_GT(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), windowPoints);
}

TEST_F(ChartPanelTest, ResetClearsSamplesPointsAndMarkers) {
  panel.reset({"elastic", "exact", "box2d"});
  panel.setBaselineShown(true);
  addRun(panel, 0, 300, 0.01);
  addRun(panel, 1, 300, 0.01);
  addRun(panel, 2, 300, 0.01);
  addBaseline(panel, 300, 0.01);
  panel.addMarker(1.0, "grab");
  panel.refresh();
  ASSERT_EQ(displayedPointCount(panel, ChartPanel::kDivergenceChart, ChartPanel::kBaselineRun),
            300);
  panel.reset({"elastic", "exact"});
  panel.refresh();
  EXPECT_EQ(panel.runCount(), 2);
  EXPECT_EQ(storedSampleCount(panel, 0), 0u);
  EXPECT_EQ(storedSampleCount(panel, 1), 0u);
  EXPECT_EQ(storedSampleCount(panel, 2), 0u);
  EXPECT_EQ(storedSampleCount(panel, ChartPanel::kBaselineRun), 0u);
  EXPECT_EQ(markerCount(panel), 0);
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    for (const int run : {0, 1, 2, ChartPanel::kBaselineRun})
      EXPECT_EQ(displayedPointCount(panel, chart, run), 0) << chart << " " << run;
  }
  // Whether the baseline is shown is a setting, not history: it stays.
  EXPECT_TRUE(panel.baselineShown());
}

TEST_F(ChartPanelTest, MarkersShowWhileTheirTimeIsOnTheAxis) {
  panel.reset({"elastic"});
  panel.addMarker(5.0, "gravity");
  panel.addMarker(6.0, "grab");
  addRun(panel, 0, 600, 1.0 / 60.0);  // 10 s
  panel.refresh();
  EXPECT_EQ(markerCount(panel), 2);
  EXPECT_EQ(displayedMarkerCount(panel), 2);

  for (int i = 600; i < 2400; ++i)
    panel.addSample(0, metricsAt(i / 60.0), {});  // 40 s
  panel.refresh();
  EXPECT_EQ(displayedMarkerCount(panel), 0);  // the 20 s window has scrolled past them
  panel.setShowWholeRun(true);
  EXPECT_EQ(displayedMarkerCount(panel), 2);
}

TEST_F(ChartPanelTest, TogglesHideQuantitiesAndEmptyCharts) {
  panel.reset({"elastic"});
  addRun(panel, 0, 100, 0.01);
  toggleNamed(panel, "momentumXToggle")->setChecked(false);
  toggleNamed(panel, "momentumYToggle")->setChecked(false);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kMomentumChart, 0), 100);  // |p| still shown
  toggleNamed(panel, "momentumMagnitudeToggle")->setChecked(false);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kMomentumChart, 0), 0);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), 100);

  toggleNamed(panel, "relativeResidualToggle")->setChecked(true);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kResidualChart, 0), 100);
  toggleNamed(panel, "residualToggle")->setChecked(false);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kResidualChart, 0), 0);

  toggleNamed(panel, "wholeRunToggle")->setChecked(true);
  EXPECT_EQ(displayedPointCount(panel, ChartPanel::kEnergyChart, 0), 100);
}

TEST_F(ChartPanelTest, PlotAreasLineUpSoTheirTimeAxesMatch) {
  // The value labels differ in width (N·s, J, 1e-12) and only a column's bottom chart has time
  // labels, whose last one overhangs the plot on the right: the plots of a column of the grid
  // still start and end at the same x, so one time reads the same in each; and every plot is
  // as wide as the others, so the columns read alike.
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);
  panel.refresh();
  // Each chart lays itself out in a posted event and lining them up takes another round (as
  // in exportPng): on screen that is the next frame.
  for (int round = 0; round < 3; ++round)
    QApplication::processEvents();
  const QList<TimeChart*> charts = panel.findChildren<TimeChart*>();
  ASSERT_EQ(charts.size(), ChartPanel::kChartCount);
  const auto plotEdgesOf = [](const TimeChart* chart) {
    const QRectF plot = chart->chart()->plotArea();
    return std::pair{chart->mapTo(chart->window(), QPoint{}).x() + plot.left(),
                     chart->mapTo(chart->window(), QPoint{}).x() + plot.right()};
  };
  const auto [left, right] = plotEdgesOf(charts.front());
  int columns = 0;
  for (const TimeChart* chart : charts) {
    for (const TimeChart* other : charts) {
      if (other->x() != chart->x()) continue;  // another column
      EXPECT_NEAR(plotEdgesOf(other).first, plotEdgesOf(chart).first, 1.0)
          << chart->chart()->title().toStdString();
      EXPECT_NEAR(plotEdgesOf(other).second, plotEdgesOf(chart).second, 1.0)
          << chart->chart()->title().toStdString();
    }
    const auto [chartLeft, chartRight] = plotEdgesOf(chart);
    EXPECT_NEAR(chartRight - chartLeft, right - left, 1.0) << chart->chart()->title().toStdString();
    columns += chart->x() == charts.front()->x() ? 0 : 1;
  }
  EXPECT_GT(columns, 0) << "a 1400 × 1000 panel has two columns of charts";
}

TEST_F(ChartPanelTest, CsvHoldsEveryStoredSampleAndParsesBack) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.csv");
  panel.reset({"elastic", "exact, tuned", "box2d:substeps=8"});
  panel.setBaselineShown(true);
  addRun(panel, 0, 250, 0.01);
  addRun(panel, 1, 40, 0.05);
  addRun(panel, 2, 70, 0.02);
  addBaseline(panel, 30, 0.1);
  ASSERT_TRUE(panel.exportCsv(path));

  const QList<QByteArray> lines = csvLines(path);
  ASSERT_GE(lines.size(), 1);
  EXPECT_EQ(lines[0], kChartCsvHeader);
  // The columns of `fooball-cli run --metrics` it had, then those of `compare`.
  EXPECT_TRUE(
      lines[0].startsWith("run,time,kinetic_energy,potential_energy,total_energy,"
                          "momentum_x,momentum_y,momentum_magnitude,energy_residual,"
                          "relative_energy_residual,"));
  EXPECT_TRUE(lines[0].endsWith(",rms_position_difference,max_position_difference"));
  ASSERT_EQ(static_cast<std::size_t>(lines.size() - 1),
            storedSampleCount(panel, 0) + storedSampleCount(panel, 1) +
                storedSampleCount(panel, 2) + storedSampleCount(panel, ChartPanel::kBaselineRun));

  constexpr int kBaselineRow = 3;
  std::array<int, 4> rowsPerRun{};
  int lastRun = 0;
  for (qsizetype i = 1; i < lines.size(); ++i) {
    QByteArray line = lines[i];
    int run = 0;
    if (line.startsWith("\"exact, tuned\",")) {
      run = 1;
      line.remove(0, static_cast<qsizetype>(sizeof("\"exact, tuned\"") - 1));
      line.prepend("exact");
    } else if (line.startsWith("box2d:substeps=8,")) {
      run = 2;
    } else if (line.startsWith("baseline,")) {
      run = kBaselineRow;
    }
    EXPECT_GE(run, lastRun) << "runs in order, the baseline last";
    lastRun = run;
    const QList<QByteArray> fields = line.split(',');
    ASSERT_EQ(fields.size(), 12) << line.toStdString();
    constexpr std::array kRunFields{"elastic", "exact", "box2d:substeps=8", "baseline"};
    EXPECT_EQ(fields[0], kRunFields[static_cast<std::size_t>(run)]);
    ++rowsPerRun[static_cast<std::size_t>(run)];

    const double time = fields[1].toDouble();
    const bool baseline = run == kBaselineRow;
    const Metrics expected = baseline ? baselineMetricsAt(time) : metricsAt(time, run);
    const Divergence divergence = baseline ? baselineDivergenceAt(time) : divergenceAt(time, run);
    const double initialEnergy =
        (baseline ? baselineMetricsAt(0.0) : metricsAt(0.0, run)).sums.totalEnergy();
    EXPECT_EQ(fields[2].toDouble(), expected.sums.kineticEnergy);
    EXPECT_EQ(fields[3].toDouble(), expected.sums.potentialEnergy);
    EXPECT_EQ(fields[4].toDouble(), expected.sums.totalEnergy());
    EXPECT_EQ(fields[5].toDouble(), expected.sums.momentum.x);
    EXPECT_EQ(fields[6].toDouble(), expected.sums.momentum.y);
    EXPECT_EQ(fields[7].toDouble(), std::hypot(expected.sums.momentum.x, expected.sums.momentum.y));
    EXPECT_EQ(fields[8].toDouble(), expected.energyResidual);
    EXPECT_EQ(fields[9].toDouble(), expected.energyResidual / std::abs(initialEnergy));
    EXPECT_EQ(fields[10].toDouble(), divergence.rmsPositionDifference);
    EXPECT_EQ(fields[11].toDouble(), divergence.maxPositionDifference);
    if (run == 0) {
      EXPECT_EQ(fields[10], "0");  // run 0 is the reference
      EXPECT_EQ(fields[11], "0");
    }
  }
  EXPECT_EQ(rowsPerRun, (std::array{250, 40, 70, 30}));
}

TEST_F(ChartPanelTest, CsvLeavesOutAHiddenBaseline) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.csv");
  panel.reset({"elastic", "exact"});
  panel.setBaselineShown(true);
  addRun(panel, 0, 20, 0.01);
  addRun(panel, 1, 20, 0.01);
  addBaseline(panel, 20, 0.01);
  panel.setBaselineShown(false);
  ASSERT_TRUE(panel.exportCsv(path));
  const QList<QByteArray> lines = csvLines(path);
  ASSERT_EQ(lines.size(), 41);
  EXPECT_FALSE(std::any_of(lines.begin(), lines.end(),
                           [](const QByteArray& line) { return line.startsWith("baseline,"); }));
}

TEST_F(ChartPanelTest, CsvToAnUnwritablePathFails) {
  EXPECT_FALSE(panel.exportCsv("/nonexistent-directory/charts.csv"));
}

/// Whether some pixel of `image` is within `tolerance` of `colour` in every channel.
bool containsColour(const QImage& image, const QColor& colour, int tolerance) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < rgb.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
    for (int x = 0; x < rgb.width(); ++x) {
      if (std::abs(qRed(line[x]) - colour.red()) <= tolerance &&
          std::abs(qGreen(line[x]) - colour.green()) <= tolerance &&
          std::abs(qBlue(line[x]) - colour.blue()) <= tolerance) {
        return true;
      }
    }
  }
  return false;
}

/// The share of the pixel columns of `area` (in `rgb`, Format_RGB32) that hold a pixel within
/// `tolerance` of `colour` in every channel: how much of a plot's width a curve of that colour
/// covers.
double columnsWithColour(const QImage& rgb, const QRect& area, const QColor& colour,
                         int tolerance) {
  int columns = 0;
  for (int x = area.left(); x <= area.right(); ++x) {
    for (int y = area.top(); y <= area.bottom(); ++y) {
      const QRgb pixel = rgb.pixel(x, y);
      if (std::abs(qRed(pixel) - colour.red()) <= tolerance &&
          std::abs(qGreen(pixel) - colour.green()) <= tolerance &&
          std::abs(qBlue(pixel) - colour.blue()) <= tolerance) {
        ++columns;
        break;
      }
    }
  }
  return double(columns) / double(area.width());
}

TEST_F(FourRunsAndBaseline, PngDrawsEveryRunsCurvesInItsColourWhereItsDataIs) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.png");
  panel.addMarker(8.0, "gravity");
  ASSERT_TRUE(panel.exportPng(path));

  QImage loaded;
  ASSERT_TRUE(loaded.load(path));
  const QImage image = loaded.convertToFormat(QImage::Format_RGB32);
  EXPECT_EQ(image.width(), 2 * panel.width());  // twice the screen's pixels
  EXPECT_GT(image.height(), panel.height());    // the panel less its toolbar, doubled
  // In every chart's plot, as drawn in the file: the 10 s fed fill the first half of the 20 s
  // window, so each run's curves (in its colour; dashed styles and crossings leave gaps) cover
  // most columns of that half and none of the rest. Run 0 has no divergence curve; the grey
  // dashed baseline has only that one.
  const QList<TimeChart*> charts = panel.findChildren<TimeChart*>();
  ASSERT_EQ(charts.size(), ChartPanel::kChartCount);
  for (const TimeChart* chart : charts) {
    const std::string title = chart->valueAxisTitle().toStdString();
    const bool divergence =
        chart->valueAxisTitle() == displayedValueAxisTitle(panel, ChartPanel::kDivergenceChart);
    const QWidget* area = chart;  // the widget the file draws: twice its size
    while (area != nullptr && area->size() * 2 != image.size())
      area = area->parentWidget();
    ASSERT_NE(area, nullptr);
    const QRectF plot = chart->chart()->plotArea();
    const QPoint origin = 2 * chart->mapTo(area, plot.topLeft().toPoint());
    const QSize size = 2 * plot.size().toSize();
    const QRect data(origin, QSize(size.width() / 2, size.height()));
    const QRect after(origin + QPoint(size.width() * 21 / 40, 0),
                      QSize(size.width() * 19 / 40, size.height()));
    for (int run = 0; run < kRuns; ++run) {
      const QColor colour = colours::runColour(run);
      const bool drawn = run > 0 || !divergence;
      EXPECT_GE(columnsWithColour(image, data, colour, 24), drawn ? 0.75 : 0.0)
          << title << ", run " << run;
      EXPECT_LE(columnsWithColour(image, data, colour, 24), drawn ? 1.0 : 0.01)
          << title << ", run " << run;
      EXPECT_LE(columnsWithColour(image, after, colour, 24), 0.01) << title << ", run " << run;
    }
    const double baseline = columnsWithColour(image, data, colours::neutralColour(), 6);
    if (divergence) {
      EXPECT_GE(baseline, 0.5) << title;
    } else {
      EXPECT_LE(baseline, 0.01) << title;
    }
    EXPECT_LE(columnsWithColour(image, after, colours::neutralColour(), 6), 0.01) << title;
  }
}

TEST(HiddenChartPanel, PngDrawsTheChartsAtThePanelsSize) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.png");
  ChartPanel panel;  // never shown, like the panel of a closed dock
  panel.resize(700, 900);
  panel.reset({"elastic"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  ASSERT_TRUE(panel.exportPng(path));

  QImage image;
  ASSERT_TRUE(image.load(path));
  EXPECT_EQ(image.width(), 1400);
  EXPECT_GT(image.height(), 1600);
  EXPECT_LT(image.height(), 1800);
  // The total energy curve (near white) is drawn.
  EXPECT_TRUE(containsColour(image, QColor(0xf5, 0xf5, 0xf5), 10));
}

TEST_F(FourRunsAndBaseline, PngHasItsCaptionAboveTheChartsAndNoSplitterGrips) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString plainPath = directory.filePath("plain.png");
  const QString captionedPath = directory.filePath("captioned.png");
  const QString caption = "FooBall — gas, 300 balls, t = 6.00 s — runs: elastic (reference), exact";
  ASSERT_TRUE(panel.exportPng(plainPath));
  ASSERT_TRUE(panel.exportPng(captionedPath, caption));
  QImage plain;
  QImage captioned;
  ASSERT_TRUE(plain.load(plainPath));
  ASSERT_TRUE(captioned.load(captionedPath));
  EXPECT_EQ(captioned.text("Description"), caption);
  EXPECT_EQ(captioned.width(), plain.width());
  const int captionHeight = captioned.height() - plain.height();
  EXPECT_GT(captionHeight, 2 * 12) << "a line of text at twice the pixels";
  EXPECT_LT(captionHeight, 2 * 60);
  // Light text on the dark strip above the charts.
  int light = 0;
  for (int y = 0; y < captionHeight; ++y) {
    for (int x = 0; x < captioned.width(); ++x)
      light += QColor(captioned.pixel(x, y)).lightnessF() > 0.7 ? 1 : 0;
  }
  EXPECT_GT(light, 200);
  // The charts below the caption are the plain export's, pixel for pixel.
  EXPECT_EQ(captioned.copy(0, captionHeight, plain.width(), plain.height())
                .convertToFormat(QImage::Format_RGB32),
            plain.convertToFormat(QImage::Format_RGB32));
  // No splitter in the panel, so no grips in any image of it.
  EXPECT_TRUE(panel.findChildren<QSplitterHandle*>().isEmpty());
}

TEST_F(ChartPanelTest, EveryToggleShowsACheckBoxOnAndOff) {
  // Off, a text-only tool button reads as a plain label: each switch carries a box that is
  // ticked when on and empty when off.
  const ChartToolBar* toolBar = panel.findChild<ChartToolBar*>();
  ASSERT_NE(toolBar, nullptr);
  const QList<QToolButton*> buttons = toolBar->findChildren<QToolButton*>();
  EXPECT_EQ(buttons.size(), 10) << "one button per switch";
  for (const QToolButton* button : buttons)
    EXPECT_EQ(button->toolButtonStyle(), Qt::ToolButtonTextBesideIcon);
  int toggles = 0;
  for (QAction* action : toolBar->actions()) {
    if (!action->isCheckable()) continue;
    ++toggles;
    const QIcon icon = action->icon();
    ASSERT_FALSE(icon.isNull()) << action->text().toStdString();
    const QImage on = icon.pixmap(QSize(16, 16), QIcon::Normal, QIcon::On).toImage();
    const QImage off = icon.pixmap(QSize(16, 16), QIcon::Normal, QIcon::Off).toImage();
    EXPECT_NE(on, off) << action->text().toStdString();
    // The empty box is drawn, not blank.
    int drawn = 0;
    for (int y = 0; y < off.height(); ++y) {
      for (int x = 0; x < off.width(); ++x)
        drawn += qAlpha(off.pixel(x, y)) > 128 ? 1 : 0;
    }
    EXPECT_GT(drawn, 20) << action->text().toStdString();
  }
  EXPECT_EQ(toggles, 10);
}

TEST(ChartGrid, ColumnsFollowTheShapeOfThePanel) {
  EXPECT_EQ(chartColumns(4, QSize(1110, 220)), 4) << "a wide strip under the box";
  EXPECT_EQ(chartColumns(3, QSize(1110, 220)), 3);
  EXPECT_EQ(chartColumns(4, QSize(1100, 600)), 2);
  EXPECT_EQ(chartColumns(4, QSize(400, 900)), 1) << "a tall column beside it";
  EXPECT_EQ(chartColumns(4, QSize(700, 200)), 2) << "none narrower than 240 px";
  EXPECT_EQ(chartColumns(1, QSize(2000, 300)), 1);
}

TEST_F(ChartPanelTest, PngToAnUnwritablePathFails) {
  EXPECT_FALSE(panel.exportPng("/nonexistent-directory/charts.png"));
}

TEST(ChartAxes, NiceStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceStep(0.7), 1.0);
  EXPECT_DOUBLE_EQ(niceStep(1.0), 1.0);
  EXPECT_DOUBLE_EQ(niceStep(1.3), 2.0);
  EXPECT_DOUBLE_EQ(niceStep(4.0), 5.0);
  EXPECT_DOUBLE_EQ(niceStep(0.2), 0.2);
  EXPECT_DOUBLE_EQ(niceStep(6e-13), 1e-12);
  EXPECT_DOUBLE_EQ(niceStep(0.0), 1.0);
}

TEST(ChartAxes, ValueAxisHoldsTheDataAndKeepsItsRangeWhileItFits) {
  ValueRange data;
  data.include(-3.2);
  data.include(7.9);
  const AxisScale scale = followValues(data, std::nullopt, 6);
  EXPECT_LT(scale.min, -3.2);
  EXPECT_GT(scale.max, 7.9);
  EXPECT_DOUBLE_EQ(std::remainder(scale.min, scale.tickInterval), 0.0);

  ValueRange wandering;
  wandering.include(-1.0);
  wandering.include(6.0);
  const AxisScale kept = followValues(wandering, scale, 6);
  EXPECT_EQ(kept.min, scale.min);
  EXPECT_EQ(kept.max, scale.max);

  ValueRange shrunk;
  shrunk.include(0.0);
  shrunk.include(0.1);
  EXPECT_LT(followValues(shrunk, scale, 6).max, 1.0);
}

TEST(ChartAxes, ConstantValuesGetAnAxisAroundThem) {
  ValueRange constant;
  constant.include(12.5);
  const AxisScale scale = followValues(constant, std::nullopt, 6);
  EXPECT_LT(scale.min, 12.5);
  EXPECT_GT(scale.max, 12.5);
  ValueRange zero;
  zero.include(0.0);
  EXPECT_LT(followValues(zero, std::nullopt, 6).min, 0.0);
}

TEST(ChartAxes, TimeAxisScrollsAndGrows) {
  const AxisScale filling = scrollingTimeScale(0.0, 5.0, 20.0);
  EXPECT_EQ(filling.min, 0.0);
  EXPECT_EQ(filling.max, 20.0);
  const AxisScale scrolled = scrollingTimeScale(0.0, 31.5, 20.0);
  EXPECT_EQ(scrolled.min, 11.5);
  EXPECT_EQ(scrolled.max, 31.5);
  EXPECT_EQ(scrolled.tickInterval, 5.0);
  const AxisScale grown = growingTimeScale(0.0, 23.0);
  EXPECT_EQ(grown.min, 0.0);
  EXPECT_EQ(grown.max, 25.0);
}

TEST(ChartAxes, LabelsHaveTheDigitsTheTicksNeed) {
  EXPECT_EQ(tickLabelFormat({0.0, 1500.0, 500.0}), "%.0f");
  EXPECT_EQ(tickLabelFormat({-1.0, 1.0, 0.5}), "%.1f");
  EXPECT_EQ(tickLabelFormat({12.4, 12.6, 0.05}), "%.2f");
  EXPECT_EQ(tickLabelFormat({-2e-12, 6e-12, 2e-12}), "%.1g");
  EXPECT_EQ(tickLabelFormat({0.0, 4e6, 1e6}), "%.1g");
}

/// `count` samples a millisecond apart with total energy 1 J, but 9 J at sample `spikeAt`.
SampleHistory flatHistoryWithSpike(int count, int spikeAt) {
  SampleHistory history;
  for (int i = 0; i < count; ++i) {
    ChartSample sample;
    sample.time = i * 0.001;
    sample[Quantity::TotalEnergy] = i == spikeAt ? 9.0 : 1.0;
    history.add(sample);
  }
  return history;
}

TEST(ChartDecimation, SpikeSurvivesAndPointsStayBounded) {
  const SampleHistory history = flatHistoryWithSpike(100'000, 54'321);
  QList<QPointF> points;
  const ValueRange range =
      fillSeriesPoints(history, Quantity::TotalEnergy, 0.0, 100.0, kMaxPoints, points);
  EXPECT_LE(points.size(), kMaxPoints);
  EXPECT_GT(points.size(), kMaxPoints / 4);
  EXPECT_EQ(range.high, 9.0);
  EXPECT_TRUE(std::any_of(points.begin(), points.end(),
                          [](const QPointF& point) { return point.y() == 9.0; }));
  for (qsizetype i = 1; i < points.size(); ++i)
    EXPECT_LT(points[i - 1].x(), points[i].x());
}

TEST(ChartDecimation, FewSamplesAreAllKeptAndNonFiniteOnesLeftOut) {
  SampleHistory history;
  for (int i = 0; i < 10; ++i) {
    ChartSample sample;
    sample.time = i * 0.1;
    sample[Quantity::RelativeEnergyResidual] = i == 5 ? std::nan("") : 1e-9 * i;
    history.add(sample);
  }
  QList<QPointF> points;
  fillSeriesPoints(history, Quantity::RelativeEnergyResidual, 0.0, 1.0, kMaxPoints, points);
  EXPECT_EQ(points.size(), 9);
  // For a log axis the zero at i = 0 goes too.
  fillSeriesPoints(history, Quantity::RelativeEnergyResidual, 0.0, 1.0, kMaxPoints, points, true);
  EXPECT_EQ(points.size(), 8);
}

TEST(ChartDecimation, LogAxisKeepsOnlyPositiveValuesWhenDecimating) {
  SampleHistory history;
  for (int i = 0; i < 20'000; ++i) {
    ChartSample sample;
    sample.time = i * 0.001;
    sample[Quantity::RmsPositionDifference] = i % 2 == 0 ? 0.0 : 1e-9 * (1 + i);
    history.add(sample);
  }
  QList<QPointF> points;
  const ValueRange range = fillSeriesPoints(history, Quantity::RmsPositionDifference, 0.0, 20.0,
                                            kMaxPoints, points, true);
  EXPECT_LE(points.size(), kMaxPoints);
  EXPECT_GT(points.size(), kMaxPoints / 4);
  EXPECT_TRUE(std::all_of(points.begin(), points.end(),
                          [](const QPointF& point) { return point.y() > 0.0; }));
  // The decimated stretches' lowest values are the zeros, so what is left of them is their
  // highest: the curve keeps its upper envelope and its peak.
  EXPECT_GT(range.low, 0.0);
  EXPECT_EQ(range.high, 1e-9 * 20'000);
}

TEST(ChartAxes, LogAxisEndsOnLabelledDecadesAroundTheData) {
  ValueRange data;
  data.include(3e-13);
  data.include(2e2);
  const LogAxisScale scale = followLogValues(data, std::nullopt, 6);
  EXPECT_LE(scale.min(), 3e-13);
  EXPECT_GE(scale.max(), 2e2);
  EXPECT_EQ((scale.highExponent - scale.lowExponent) % scale.decadesPerTick, 0);
  EXPECT_LE((scale.highExponent - scale.lowExponent) / scale.decadesPerTick, 6);
  EXPECT_EQ(scale.lowExponent % scale.decadesPerTick, 0);  // labels at round decades
  // Within a decade: one decade, not a point.
  ValueRange narrow;
  narrow.include(2e-6);
  narrow.include(3e-6);
  const LogAxisScale tight = followLogValues(narrow, std::nullopt, 6);
  EXPECT_EQ(tight.lowExponent, -6);
  EXPECT_EQ(tight.highExponent, -5);
  // Kept while the data wanders inside it, narrowed when the data shrinks by far more, widened
  // when it grows out.
  ValueRange wandered;
  wandered.include(1e-12);
  wandered.include(5e1);
  const LogAxisScale kept = followLogValues(wandered, scale, 6);
  EXPECT_EQ(kept.lowExponent, scale.lowExponent);
  EXPECT_EQ(kept.highExponent, scale.highExponent);
  EXPECT_EQ(followLogValues(narrow, scale, 6).lowExponent, -6);
  ValueRange grown = narrow;
  grown.include(5e4);
  EXPECT_GE(followLogValues(grown, tight, 6).max(), 5e4);
}

}  // namespace
}  // namespace fooball::gui
