#include "time_chart.h"

#include <gtest/gtest.h>

#include <QtTest/QTest>
#include <deque>

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
    view.setRuns({QStringLiteral("elastic")});
    view.resize(400, 300);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  }
}

}  // namespace
}  // namespace fooball::gui
