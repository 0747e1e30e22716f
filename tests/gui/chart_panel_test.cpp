#include "chart_panel.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "axis_scale.h"
#include "chart_csv.h"
#include "series_points.h"
#include "time_chart.h"

namespace fooball::gui {
namespace {

constexpr int kMaxPoints = TimeChart::kMaxPointsPerCurve;

/// A plausible state at `time` (s): energy sloshing between kinetic and potential, momentum
/// turning, a residual that grows; `runIndex` shifts the numbers so two runs differ.
Metrics metricsAt(double time, int runIndex = 0) {
  Metrics metrics;
  metrics.time = time;
  const double phase = time + runIndex;
  metrics.sums.kineticEnergy = 50.0 + 20.0 * std::sin(phase);
  metrics.sums.potentialEnergy = 30.0 - 20.0 * std::sin(phase);
  metrics.sums.momentum = {4.0 * std::cos(phase), 3.0 * std::sin(0.5 * phase)};
  metrics.energyResidual = (1.0 + runIndex) * 1e-6 * time;
  return metrics;
}

void addRun(ChartPanel& panel, int runIndex, int count, double dt) {
  for (int i = 0; i < count; ++i)
    panel.addSample(runIndex, metricsAt(i * dt, runIndex));
}

/// A panel on screen (offscreen) and wide enough for 2000 points per curve, as in a dock.
class ChartPanelTest : public testing::Test {
 protected:
  ChartPanelTest() {
    panel.resize(1400, 1000);
    panel.show();
    QApplication::processEvents();
  }

  ChartPanel panel;
};

TEST_F(ChartPanelTest, CompareModeDrawsBothRunsInEveryChart) {
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);
  panel.refresh();
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    EXPECT_GT(panel.displayedPointCount(chart, 0), 0) << "chart " << chart;
    EXPECT_GT(panel.displayedPointCount(chart, 1), 0) << "chart " << chart;
  }
}

TEST_F(ChartPanelTest, SingleModeDrawsRunZeroOnly) {
  panel.reset({"elastic"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);  // no such run: ignored
  panel.refresh();
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    EXPECT_EQ(panel.displayedPointCount(chart, 0), 600) << "chart " << chart;
    EXPECT_EQ(panel.displayedPointCount(chart, 1), 0) << "chart " << chart;
  }
  EXPECT_EQ(panel.storedSampleCount(1), 0u);
}

TEST_F(ChartPanelTest, ViewWaitsForARefresh) {
  panel.reset({"elastic"});
  addRun(panel, 0, 100, 0.01);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kEnergyChart, 0), 0);
  EXPECT_EQ(panel.storedSampleCount(0), 100u);
  panel.refresh();
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kEnergyChart, 0), 100);
}

TEST_F(ChartPanelTest, PointsStayBoundedForLongRuns) {
  panel.reset({"elastic", "exact"});
  // 10⁵ samples a millisecond apart: the 20 s window alone holds 20 000 of them.
  addRun(panel, 0, 100'000, 1e-3);
  addRun(panel, 1, 100'000, 1e-3);
  EXPECT_LE(panel.storedSampleCount(0),
            SampleHistory::kDefaultWholeRunCapacity + SampleHistory::kDefaultRecentCapacity);
  for (const bool wholeRun : {false, true}) {
    panel.setShowWholeRun(wholeRun);
    panel.refresh();
    for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
      for (int run = 0; run < 2; ++run) {
        EXPECT_GT(panel.displayedPointCount(chart, run), kMaxPoints / 4);
        EXPECT_LE(panel.displayedPointCount(chart, run), kMaxPoints);
      }
    }
  }
}

TEST_F(ChartPanelTest, WholeRunShowsMoreThanTheWindow) {
  panel.reset({"elastic"});
  addRun(panel, 0, 6000, 1.0 / 60.0);  // 100 s
  panel.setWindowSeconds(20.0);
  panel.refresh();
  const int windowPoints = panel.displayedPointCount(ChartPanel::kEnergyChart, 0);
  EXPECT_NEAR(windowPoints, 20 * 60, 2);
  panel.setShowWholeRun(true);
  EXPECT_GT(panel.displayedPointCount(ChartPanel::kEnergyChart, 0), windowPoints);
}

TEST_F(ChartPanelTest, ResetClearsSamplesPointsAndMarkers) {
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 300, 0.01);
  addRun(panel, 1, 300, 0.01);
  panel.addMarker(1.0, "grab");
  panel.refresh();
  panel.reset({"elastic"});
  panel.refresh();
  EXPECT_EQ(panel.storedSampleCount(0), 0u);
  EXPECT_EQ(panel.markerCount(), 0);
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    EXPECT_EQ(panel.displayedPointCount(chart, 0), 0);
    EXPECT_EQ(panel.displayedPointCount(chart, 1), 0);
  }
}

TEST_F(ChartPanelTest, MarkersShowWhileTheirTimeIsOnTheAxis) {
  panel.reset({"elastic"});
  panel.addMarker(5.0, "gravity");
  panel.addMarker(6.0, "grab");
  addRun(panel, 0, 600, 1.0 / 60.0);  // 10 s
  panel.refresh();
  EXPECT_EQ(panel.markerCount(), 2);
  EXPECT_EQ(panel.displayedMarkerCount(), 2);

  for (int i = 600; i < 2400; ++i)
    panel.addSample(0, metricsAt(i / 60.0));  // 40 s
  panel.refresh();
  EXPECT_EQ(panel.displayedMarkerCount(), 0);  // the 20 s window has scrolled past them
  panel.setShowWholeRun(true);
  EXPECT_EQ(panel.displayedMarkerCount(), 2);
}

QAction* toggleNamed(ChartPanel& panel, const char* name) {
  auto* toggle = panel.findChild<QAction*>(name);
  EXPECT_NE(toggle, nullptr) << name;
  return toggle;
}

TEST_F(ChartPanelTest, TogglesHideQuantitiesAndEmptyCharts) {
  panel.reset({"elastic"});
  addRun(panel, 0, 100, 0.01);
  toggleNamed(panel, "momentumXToggle")->setChecked(false);
  toggleNamed(panel, "momentumYToggle")->setChecked(false);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kMomentumChart, 0), 100);  // |p| still shown
  toggleNamed(panel, "momentumMagnitudeToggle")->setChecked(false);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kMomentumChart, 0), 0);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kEnergyChart, 0), 100);

  toggleNamed(panel, "relativeResidualToggle")->setChecked(true);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kResidualChart, 0), 100);
  toggleNamed(panel, "residualToggle")->setChecked(false);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kResidualChart, 0), 0);

  toggleNamed(panel, "wholeRunToggle")->setChecked(true);
  EXPECT_EQ(panel.displayedPointCount(ChartPanel::kEnergyChart, 0), 100);
}

TEST_F(ChartPanelTest, PlotAreasLineUpSoTheirTimeAxesMatch) {
  // The value labels differ in width (N·s, J, 1e-12) and only the bottom chart has time labels,
  // whose last one overhangs the plot on the right: every plot still starts and ends at the
  // same x, so one time reads the same in every chart.
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 600, 1.0 / 60.0);
  addRun(panel, 1, 600, 1.0 / 60.0);
  panel.refresh();
  QApplication::processEvents();
  const QList<TimeChart*> charts = panel.findChildren<TimeChart*>();
  ASSERT_EQ(charts.size(), ChartPanel::kChartCount);
  const auto plotEdgesOf = [](const TimeChart* chart) {
    const QRectF plot = chart->chart()->plotArea();
    return std::pair{chart->mapTo(chart->window(), QPoint{}).x() + plot.left(),
                     chart->mapTo(chart->window(), QPoint{}).x() + plot.right()};
  };
  const auto [left, right] = plotEdgesOf(charts.front());
  for (const TimeChart* chart : charts) {
    const auto [chartLeft, chartRight] = plotEdgesOf(chart);
    EXPECT_NEAR(chartLeft, left, 1.0) << chart->chart()->title().toStdString();
    EXPECT_NEAR(chartRight, right, 1.0) << chart->chart()->title().toStdString();
  }
}

TEST_F(ChartPanelTest, CsvHoldsEveryStoredSampleAndParsesBack) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.csv");
  panel.reset({"elastic", "exact, tuned"});
  addRun(panel, 0, 250, 0.01);
  addRun(panel, 1, 40, 0.05);
  ASSERT_TRUE(panel.exportCsv(path));

  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QList<QByteArray> lines = file.readAll().split('\n');
  ASSERT_GE(lines.size(), 2);
  EXPECT_EQ(lines[0], kChartCsvHeader);
  ASSERT_TRUE(lines.back().isEmpty());  // the last row ends its line too
  ASSERT_EQ(static_cast<std::size_t>(lines.size() - 2),
            panel.storedSampleCount(0) + panel.storedSampleCount(1));

  int rowsPerRun[2] = {0, 0};
  for (qsizetype i = 1; i + 1 < lines.size(); ++i) {
    QByteArray line = lines[i];
    int run = 0;
    if (line.startsWith("\"exact, tuned\",")) {
      run = 1;
      line.remove(0, static_cast<qsizetype>(sizeof("\"exact, tuned\"") - 1));
      line.prepend("exact");
    }
    const QList<QByteArray> fields = line.split(',');
    ASSERT_EQ(fields.size(), 10) << line.toStdString();
    EXPECT_EQ(fields[0], run == 0 ? "elastic" : "exact");
    ++rowsPerRun[run];

    const double time = fields[1].toDouble();
    const Metrics expected = metricsAt(time, run);
    EXPECT_EQ(fields[2].toDouble(), expected.sums.kineticEnergy);
    EXPECT_EQ(fields[3].toDouble(), expected.sums.potentialEnergy);
    EXPECT_EQ(fields[4].toDouble(), expected.sums.totalEnergy());
    EXPECT_EQ(fields[5].toDouble(), expected.sums.momentum.x);
    EXPECT_EQ(fields[6].toDouble(), expected.sums.momentum.y);
    EXPECT_EQ(fields[7].toDouble(), std::hypot(expected.sums.momentum.x, expected.sums.momentum.y));
    EXPECT_EQ(fields[8].toDouble(), expected.energyResidual);
    EXPECT_EQ(fields[9].toDouble(),
              expected.energyResidual / std::abs(metricsAt(0.0, run).sums.totalEnergy()));
  }
  EXPECT_EQ(rowsPerRun[0], 250);
  EXPECT_EQ(rowsPerRun[1], 40);
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

TEST_F(ChartPanelTest, PngLoadsBackWithBothRunsColours) {
  QTemporaryDir directory;
  ASSERT_TRUE(directory.isValid());
  const QString path = directory.filePath("charts.png");
  panel.reset({"elastic", "exact"});
  addRun(panel, 0, 1200, 1.0 / 60.0);
  addRun(panel, 1, 1200, 1.0 / 60.0);
  panel.addMarker(8.0, "gravity");
  ASSERT_TRUE(panel.exportPng(path));

  QImage image;
  ASSERT_TRUE(image.load(path));
  EXPECT_EQ(image.width(), 2 * panel.width());  // twice the screen's pixels
  EXPECT_GT(image.height(), panel.height());    // the panel less its toolbar, doubled
  EXPECT_TRUE(containsColour(image, ChartPanel::runColour(0), 24));
  EXPECT_TRUE(containsColour(image, ChartPanel::runColour(1), 24));
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
}

}  // namespace
}  // namespace fooball::gui
