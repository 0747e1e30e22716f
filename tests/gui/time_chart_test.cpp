#include "time_chart.h"

#include <gtest/gtest.h>

#include <QtTest/QTest>
#include <array>
#include <cmath>
#include <deque>

#include "axis_scale.h"

namespace fooball::gui {
namespace {

// A chart view built, shown and destroyed leaves no Qt Charts object behind. LeakSanitizer
// (on in the ASan test run) checks it at exit: QChartView(parent) makes a default QChart of its
// own, and a later setChart() only takes it out of the scene, so a TimeChart built that way lost
// one QChart (about 30 kB with its legend and layout) each time. Twenty of them, so that a stale
// pointer left in Qt's memory cannot hide every one from the sanitizer's scan.
TEST(TimeChart, LeavesNoChartBehind) {
  const std::deque<ChartMarker> markers;
  for (int i = 0; i < 20; ++i) {
    TimeChart view(QStringLiteral("Energy"), {Quantity::KineticEnergy}, &markers);
    view.setOwners({{0, QStringLiteral("elastic")}}, false);
    view.resize(400, 300);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  }
}

TEST(TimeChart, LogAxisDrawsPositiveValuesAndFitsThem) {
  const std::deque<ChartMarker> markers;
  TimeChart view(QStringLiteral("Divergence"), {Quantity::RmsPositionDifference}, &markers,
                 TimeChart::ValueAxisKind::Logarithmic);
  view.setOwners({{1, QStringLiteral("exact")}, {ChartData::kBaseline, QStringLiteral("baseline")}},
                 true);
  view.resize(600, 300);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));

  SampleHistory run0;
  SampleHistory run1;
  SampleHistory baseline;
  const std::array values{0.0, -2.0, 4e-11, 7e-4};
  for (std::size_t i = 0; i < values.size(); ++i) {
    ChartSample sample;
    sample.time = static_cast<double>(i);
    run0.add(sample);  // zero: run 0 is the reference, and is not drawn here anyway
    sample[Quantity::RmsPositionDifference] = values[i];
    run1.add(sample);
    sample[Quantity::RmsPositionDifference] = 1e-9;
    baseline.add(sample);
  }
  const std::array<const SampleHistory*, 2> histories{&run0, &run1};
  view.redraw(histories, &baseline, growingTimeScale(0.0, 3.0));

  EXPECT_EQ(view.pointCount(0), 0);
  const QList<QPointF> points = view.points(1, 0);
  ASSERT_EQ(points.size(), 2);
  EXPECT_EQ(points[0], QPointF(2.0, 4e-11));
  EXPECT_EQ(points[1], QPointF(3.0, 7e-4));
  EXPECT_EQ(view.pointCount(ChartData::kBaseline), 4);
  // From a whole decade at or below the lowest value to one at or above the highest; how many
  // decades a label step takes depends on the plot's height.
  const auto [low, high] = view.valueRange();
  EXPECT_LE(low, 4e-11);
  EXPECT_GE(low, 4e-15);
  EXPECT_GE(high, 7e-4);
  EXPECT_LE(high, 7.0);
  EXPECT_DOUBLE_EQ(std::log10(low), std::round(std::log10(low)));
  EXPECT_DOUBLE_EQ(std::log10(high), std::round(std::log10(high)));
}

}  // namespace
}  // namespace fooball::gui
