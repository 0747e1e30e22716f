// The Statistics dock (issue #16): opened by --show statistics or View, in front of the charts'
// tab; on the gas preset its histograms count every ball of every run as the engine does, in
// the runs' colours; its kT reads the engine's; it says when the theory does not apply; and
// while it is closed or behind the charts nothing is measured.

#include <QAction>
#include <QDockWidget>

#include "charts/chart_panel.h"
#include "charts/chart_style.h"
#include "charts/speed_histogram_chart.h"
#include "fooball/presets.h"
#include "fooball/speed_distribution.h"
#include "frames/run_feed.h"
#include "gui_fixture.h"
#include "readouts/gas_readout.h"
#include "readouts/statistics_panel.h"
#include "run_palette.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

class StatisticsDock : public GuiTest {
 protected:
  StatisticsPanel& statistics() const { return *window->statistics(); }
  const SpeedHistogramChart& histogram() const { return *statistics().histogram(); }
  QAction* toggle() const { return window->statisticsDock()->toggleViewAction(); }

  /// Opens the dock as --show statistics does, and lets the queued raise and refresh run.
  void openDock() {
    window->actions().applyShowOptions({QStringLiteral("statistics")});
    settle();
  }
  static void settle() {
    for (int i = 0; i < 5; ++i)
      QCoreApplication::processEvents();
  }

  /// Behind a tab, Qt keeps a dock "visible" and moves it out of the window's sight.
  bool onScreen(const QWidget* widget) const {
    return widget->isVisible() &&
           window->rect().intersects(QRect(widget->mapTo(window.get(), QPoint()), widget->size()));
  }

  /// Run `run`'s counts as drawn: the outline's even-numbered points hold them, bin by bin.
  std::vector<std::size_t> drawnCounts(int run) const {
    const QList<QPointF> points = histogram().histogramPoints(run);
    std::vector<std::size_t> counts;
    for (qsizetype k = 0; k < points.size(); k += 2)
      counts.push_back(static_cast<std::size_t>(std::lround(points[k].y())));
    return counts;
  }
};

TEST_F(StatisticsDock, ShowOptionOpensItInFrontOfTheCharts) {
  open(loadPreset("gas"));
  EXPECT_TRUE(window->statisticsDock()->isHidden()) << "closed at first";
  EXPECT_FALSE(toggle()->isChecked());
  openDock();
  EXPECT_TRUE(statistics().onScreen());
  EXPECT_TRUE(toggle()->isChecked());
  EXPECT_FALSE(onScreen(window->charts())) << "the charts' tab is behind it";
  EXPECT_GT(statistics().refreshCount(), 0) << "measured as soon as it was shown";
  EXPECT_EQ(window->dockWidgetArea(window->statisticsDock()), Qt::RightDockWidgetArea)
      << "a tab of the charts, beside the box";
}

TEST_F(StatisticsDock, ViewActionOpensAndClosesItAndResetLayoutClosesIt) {
  open(loadPreset("gas"));
  toggle()->trigger();
  settle();
  EXPECT_TRUE(statistics().onScreen());
  toggle()->trigger();
  settle();
  EXPECT_FALSE(statistics().onScreen());
  EXPECT_TRUE(onScreen(window->charts()));

  openDock();
  window->resetLayout();
  settle();
  EXPECT_TRUE(window->statisticsDock()->isHidden());
  EXPECT_TRUE(onScreen(window->charts()));
  toggle()->trigger();  // opened again: a tab of the charts, as at first
  settle();
  EXPECT_TRUE(window->tabifiedDockWidgets(window->statisticsDock()).contains(window->chartsDock()));
  EXPECT_TRUE(statistics().onScreen());
  EXPECT_FALSE(onScreen(window->charts()));
}

TEST_F(StatisticsDock, NothingIsMeasuredWhileClosedOrBehindTheCharts) {
  open(loadPreset("gas"));
  frames(120);  // 2 s: eight refreshes' worth
  EXPECT_EQ(statistics().refreshCount(), 0);
  EXPECT_TRUE(statistics().latest().runs.empty());

  openDock();
  const int opened = statistics().refreshCount();
  frames(60);
  EXPECT_GE(statistics().refreshCount(), opened + 3) << "about 4 a second while on screen";

  window->chartsDock()->raise();  // the charts' tab to the front
  settle();
  ASSERT_FALSE(statistics().onScreen());
  const int behind = statistics().refreshCount();
  frames(120);
  EXPECT_EQ(statistics().refreshCount(), behind);
}

TEST_F(StatisticsDock, HistogramsCountEveryBallOfEveryRunAsTheEngineDoesInTheRunsColours) {
  open(loadPreset("gas"), "elastic", {"exact", "box2d"});
  openDock();
  frames(90);
  window->feed().showStatistics();  // now, so that the runs are where they were measured
  ASSERT_EQ(histogram().histogramCount(), 3);
  for (int run = 0; run < 3; ++run) {
    const std::vector<std::size_t> counts = drawnCounts(run);
    const QList<QPointF> points = histogram().histogramPoints(run);
    ASSERT_FALSE(points.isEmpty());
    const double range = points.back().x();  // m/s, the last bin's right edge
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), std::size_t{0}), group().ballCount())
        << "run " << run << ": every ball in a bin";
    EXPECT_EQ(counts, speedHistogram(runs().run(run).velocities(), counts.size(), range).counts)
        << "run " << run;
    EXPECT_EQ(histogram().histogramPen(run).color(), colours::runColour(run));
    EXPECT_EQ(histogram().histogramName(run), runs().label(run));
    EXPECT_EQ(histogram().speedRange().second, range) << "the bins span the speed axis";
  }
  // The Maxwell–Boltzmann curve: a point per bin, and the bins' counts it expects add up to
  // nearly every ball (the axis reaches past the fastest ball).
  const QList<QPointF> curve = histogram().curvePoints();
  ASSERT_EQ(curve.size(), qsizetype(drawnCounts(0).size()));
  double expected = 0.0;
  for (const QPointF& point : curve)
    expected += point.y();
  EXPECT_NEAR(expected, double(group().ballCount()), 0.01 * double(group().ballCount()));
}

TEST_F(StatisticsDock, TemperatureReadsTheEnginesToTheDigitsShown) {
  open(loadPreset("gas"), "elastic", {"exact"});
  openDock();
  frames(30);
  window->feed().showStatistics();
  for (int run = 0; run < 2; ++run) {
    const Simulation& simulation = runs().run(run);
    const double kT = kineticTemperature(simulation.masses(), simulation.velocities());
    const QString text = statistics().readout()->text(GasReadout::kTemperature, run);
    bool ok = false;
    const double shown = text.toDouble(&ok);
    ASSERT_TRUE(ok) << text.toStdString();
    // Four significant digits: within half of the last one.
    EXPECT_NEAR(shown, kT, 5e-4 * kT) << text.toStdString();
  }
}

TEST_F(StatisticsDock, SaysWhenTheTheoryDoesNotApply) {
  open(loadPreset("gas"));
  openDock();
  frames(60);
  window->feed().showStatistics();
  GasReadout& readout = *statistics().readout();
  EXPECT_TRUE(readout.caveat().isEmpty());
  EXPECT_NE(readout.text(GasReadout::kPressureRatio, 0), QStringLiteral("n/a"));

  runs().change([](RunGroup& group) {
    WorldSettings world = group.world();
    world.gravity = {0.0, -9.81};
    group.setWorld(world);
  });
  window->feed().showStatistics();
  EXPECT_TRUE(readout.caveat().contains(QStringLiteral("gravity")))
      << readout.caveat().toStdString();
  for (const GasReadout::Row row : {GasReadout::kHendersonPressure, GasReadout::kPressureRatio,
                                    GasReadout::kEnskogRate, GasReadout::kRateRatio}) {
    EXPECT_EQ(readout.text(row, 0), QStringLiteral("n/a")) << row;
  }
  // What is measured is still shown.
  EXPECT_NE(readout.text(GasReadout::kPressure, 0), QStringLiteral("n/a"));
}

}  // namespace
}  // namespace fooball::gui::testing
