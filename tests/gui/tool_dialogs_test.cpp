// Tools → Speed vs accuracy and Tools → Failure map: they run what `fooball-cli tradeoff` and
// `failure-map` run on a worker (the window stays live), cancel without leaving a half result,
// draw the CLI's charts from the measurements, and a click on a point opens its configuration.

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLogValueAxis>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QSet>
#include <QTableWidget>
#include <QXYSeries>
#include <algorithm>
#include <functional>
#include <limits>
#include <memory>

#include "capacity_chart_builder.h"
#include "chart_image.h"
#include "charts/chart_panel.h"
#include "control/scene_commands.h"
#include "fooball/presets.h"
#include "gui_fixture.h"
#include "registry.h"
#include "tools/benchmark_dialog.h"
#include "tools/failure_map_dialog.h"
#include "tools/measured_charts.h"
#include "tools/tool_run_panel.h"
#include "tools/tradeoff_dialog.h"
#include "tradeoff_chart_builder.h"
#include "widgets/dark_theme.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

/// Only the items named `names` checked.
void checkOnly(QListWidget* list, const QStringList& names) {
  for (int row = 0; row < list->count(); ++row) {
    QListWidgetItem* item = list->item(row);
    item->setCheckState(names.contains(item->text()) ? Qt::Checked : Qt::Unchecked);
  }
}

/// The series of `view`'s chart named `name` (a legend entry), perhaps with a note in brackets
/// ("elastic (error 0: at the bottom)").
QXYSeries* seriesNamed(QChartView* view, const QString& name) {
  for (QAbstractSeries* series : view->chart()->series()) {
    if (series->name() == name || series->name().startsWith(name + QStringLiteral(" (")))
      return qobject_cast<QXYSeries*>(series);
  }
  return nullptr;
}

/// The texts `view` draws (title, axis labels and titles, legend entries) that Qt shortened
/// with an ellipsis to fit ("box2d: 5250…", "…exact run at 0…").
QStringList elidedTexts(const QChartView& view) {
  QStringList elided;
  for (QGraphicsItem* item : view.scene()->items()) {
    const auto* text = qobject_cast<const QGraphicsTextItem*>(item->toGraphicsObject());
    if (text == nullptr || !item->isVisible()) continue;
    const QString shown = text->toPlainText();
    if (shown.contains(QChar(0x2026)) || shown.contains(QStringLiteral("..."))) elided << shown;
  }
  return elided;
}

/// Every text of `dialog`'s charts whole at the window sizes of a small and a common screen.
void expectNothingElided(QWidget& dialog, const std::vector<QChartView*>& views) {
  for (const QSize size : {QSize(1000, 650), QSize(1440, 900)}) {
    dialog.resize(size);
    QCoreApplication::processEvents();
    for (QChartView* view : views) {
      EXPECT_EQ(elidedTexts(*view), QStringList())
          << "dialog " << dialog.width() << "×" << dialog.height() << ", chart '"
          << view->chart()->title().toStdString() << "'";
    }
  }
}

class Tools : public GuiTest {
 protected:
  TradeoffDialog* openTradeoff() {
    window->actions().tradeoff()->trigger();
    return window->actions().tradeoffDialog();
  }
  FailureMapDialog* openFailureMap() {
    window->actions().failureMap()->trigger();
    return window->actions().failureMapDialog();
  }
  /// Starts `dialog` with its Start button and waits for the end of the run.
  void runToEnd(ToolDialog* dialog) {
    QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
    ASSERT_TRUE(dialog->runPanel()->running())
        << dialog->runPanel()->errorLabel()->text().toStdString();
    ASSERT_TRUE(waitUntil([&] { return !dialog->runPanel()->running(); }, 30.0 * slowdown()));
    EXPECT_TRUE(dialog->runPanel()->errorLabel()->isHidden())
        << dialog->runPanel()->errorLabel()->text().toStdString();
  }
  /// Clicks `series`' point `index` as the mouse would (QXYSeries::clicked), a pixel off.
  void clickPoint(ToolDialog* dialog, QXYSeries* series, int index) {
    const QPointF value = series->at(index);
    QChart* chart = series->chart();
    const QPointF offset =
        chart->mapToValue(chart->mapToPosition(value, series) + QPointF(1, 1), series);
    dialog->charts()->pointClicked(series, offset);
  }
  /// Clicks the pixel where `series`' point `index` is drawn, with the mouse on the chart view.
  static void mouseClickPoint(QChartView* view, QXYSeries* series, int index) {
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view->window()));
    QCoreApplication::processEvents();  // the new chart's layout: its plot area
    const QPointF inScene =
        series->chart()->mapToScene(series->chart()->mapToPosition(series->at(index), series));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(inScene));
  }
  /// The point of `series` furthest on screen from its nearest neighbour. The tradeoff's x is
  /// measured CPU time, so two settings that cost about the same (small substep counts, where
  /// the per-step overhead dominates; more so under a sanitizer) can be drawn on top of each
  /// other, and a click there cannot tell them apart.
  static int mostIsolatedPoint(QXYSeries* series) {
    QChart* chart = series->chart();
    int best = 0;
    double bestGap = -1.0;
    for (int i = 0; i < series->count(); ++i) {
      double gap = std::numeric_limits<double>::infinity();
      for (int j = 0; j < series->count(); ++j) {
        if (j == i) continue;
        const QPointF offset = chart->mapToPosition(series->at(i), series) -
                               chart->mapToPosition(series->at(j), series);
        gap = std::min(gap, QPointF::dotProduct(offset, offset));
      }
      if (gap > bestGap) {
        bestGap = gap;
        best = i;
      }
    }
    return best;
  }
  void expectIdle(ToolDialog* dialog) {
    EXPECT_FALSE(dialog->runPanel()->running());
    EXPECT_TRUE(dialog->runPanel()->startButton()->isEnabled());
    EXPECT_FALSE(dialog->runPanel()->cancelButton()->isEnabled());
    EXPECT_FALSE(runs().paused()) << "the simulation continues after the run";
  }
};

TEST_F(Tools, AreInTheToolsMenu) {
  open(stillBalls());
  for (QAction* menu : window->menuBar()->actions()) {
    if (menu->text() != QStringLiteral("&Tools")) continue;
    EXPECT_TRUE(menu->menu()->actions().contains(window->actions().tradeoff()));
    EXPECT_TRUE(menu->menu()->actions().contains(window->actions().failureMap()));
  }
  EXPECT_TRUE(openTradeoff()->isVisible());
  EXPECT_TRUE(openFailureMap()->isVisible());
}

TEST_F(Tools, TradeoffRunsWithoutBlockingTheWindowAndChartsEachSetting) {
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  dialog->presetBox()->setCurrentText(QStringLiteral("gas"));
  checkOnly(dialog->backendList(), {QStringLiteral("elastic")});
  dialog->durationEdit()->setText(QStringLiteral("0.5"));

  // A heartbeat of posted events on the GUI thread (as the benchmark's test): it beats during
  // the run only if the measuring runs elsewhere.
  int beatsDuringRun = 0;
  bool beating = true;
  std::function<void()> beat = [&] {
    if (!beating) return;
    if (dialog->runPanel()->running()) ++beatsDuringRun;
    QMetaObject::invokeMethod(dialog, beat, Qt::QueuedConnection);
  };
  QMetaObject::invokeMethod(dialog, beat, Qt::QueuedConnection);
  const QString beforeStart = dialog->charts()->placeholder();
  EXPECT_TRUE(beforeStart.startsWith(QStringLiteral("Press Start")));
  QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
  EXPECT_TRUE(dialog->runPanel()->running());
  EXPECT_TRUE(dialog->charts()->placeholder().startsWith(QStringLiteral("Measuring")))
      << "not 'Press Start' while it runs";
  EXPECT_TRUE(runs().paused()) << "the simulation pauses while the tool measures";
  EXPECT_TRUE(dialog->runPanel()->cancelButton()->isEnabled());
  EXPECT_FALSE(dialog->durationEdit()->isEnabled());
  ASSERT_TRUE(waitUntil([&] { return !dialog->runPanel()->running(); }, 30.0 * slowdown()));
  beating = false;
  QCoreApplication::processEvents();
  EXPECT_GT(beatsDuringRun, 1) << "the event loop ran while the measurement did";
  expectIdle(dialog);
  EXPECT_EQ(dialog->runPanel()->progressBar()->value(),
            dialog->runPanel()->progressBar()->maximum());

  // elastic at 1 … 64 substeps.
  const std::vector<measure::TradeoffPoint>& points = dialog->points();
  ASSERT_EQ(points.size(), 7u);
  const std::vector<QChartView*>& views = dialog->charts()->views();
  ASSERT_EQ(views.size(), 2u) << "cost against trajectory error, then against energy error";
  for (std::size_t panel = 0; panel < views.size(); ++panel) {
    QXYSeries* elastic = seriesNamed(views[panel], QStringLiteral("elastic"));
    ASSERT_NE(elastic, nullptr);
    ASSERT_EQ(elastic->count(), 7);
    for (int i = 0; i < elastic->count(); ++i) {
      const measure::TradeoffPoint& point = points[std::size_t(i)];
      const double error = panel == 0 ? point.trajectoryError : point.energyError;
      EXPECT_EQ(elastic->at(i).x(), point.cpuMsPerSimulatedSecond);
      if (error > 0.0) {
        EXPECT_EQ(elastic->at(i).y(), error) << "panel " << panel;
      }
    }
  }
}

TEST_F(Tools, TradeoffPointOpensItsSettingAgainstTheReference) {
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  dialog->presetBox()->setCurrentText(QStringLiteral("head-on"));
  checkOnly(dialog->backendList(), {QStringLiteral("elastic")});
  dialog->durationEdit()->setText(QStringLiteral("0.3"));
  runToEnd(dialog);
  QXYSeries* elastic = seriesNamed(dialog->charts()->views().at(1), QStringLiteral("elastic"));
  ASSERT_NE(elastic, nullptr);
  ASSERT_EQ(elastic->count(), 7);
  // elastic at 1, 2, 4 … 64 substeps, in that order.
  const int index = mostIsolatedPoint(elastic);
  clickPoint(dialog, elastic, index);

  ASSERT_EQ(runs().runCount(), 2);
  EXPECT_EQ(runs().group().spec(0),
            (RunSpec{"elastic", {"substeps=" + std::to_string(1 << index)}}));
  EXPECT_EQ(runs().group().spec(1), (RunSpec{"exact", {}}));
  const Scene headOn = loadPreset("head-on");
  const Scene& loaded = runs().group().loadedScene();
  EXPECT_EQ(loaded.name, headOn.name);
  ASSERT_EQ(loaded.balls.size(), headOn.balls.size());
  for (std::size_t i = 0; i < loaded.balls.size(); ++i) {
    EXPECT_EQ(loaded.balls[i].position, headOn.balls[i].position);
    EXPECT_EQ(loaded.balls[i].velocity, headOn.balls[i].velocity);
  }
}

TEST_F(Tools, ParetoFrontPointOpensUnderTheMouse) {
  // The front is drawn over the points on it: a click there reached the line, which opened
  // nothing.
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  dialog->presetBox()->setCurrentText(QStringLiteral("gas"));
  checkOnly(dialog->backendList(), {QStringLiteral("elastic")});
  dialog->durationEdit()->setText(QStringLiteral("0.3"));
  runToEnd(dialog);
  QChartView* view = dialog->charts()->views().at(0);  // trajectory errors: none zero
  QXYSeries* front = nullptr;                          // the only series without a legend entry
  for (QAbstractSeries* series : view->chart()->series()) {
    if (series->name().isEmpty()) front = qobject_cast<QXYSeries*>(series);
  }
  ASSERT_NE(front, nullptr);
  ASSERT_GE(front->count(), 2) << "a front of several settings";
  const int index = mostIsolatedPoint(front);
  const double cost = front->at(index).x();
  const auto point = std::ranges::find_if(dialog->points(), [&](const auto& measured) {
    return measured.cpuMsPerSimulatedSecond == cost;
  });
  ASSERT_NE(point, dialog->points().end());
  mouseClickPoint(view, front, index);
  ASSERT_EQ(runs().runCount(), 2) << "the front point opened against the reference";
  EXPECT_EQ(runs().group().spec(0), (RunSpec{point->setting.backend, point->setting.options}));
}

TEST_F(Tools, CircledFailingPointOpensUnderTheMouse) {
  // The circles are drawn over the curves' points: a click there opened nothing.
  open(stillBalls());
  FailureMapDialog* dialog = openFailureMap();
  checkOnly(dialog->sweepList(), {QStringLiteral("tunnelling")});
  checkOnly(dialog->backendList(), {QStringLiteral("xpbd")});
  runToEnd(dialog);
  QChartView* view = dialog->charts()->views().at(0);
  QXYSeries* failing = seriesNamed(view, QStringLiteral("failing point"));
  ASSERT_NE(failing, nullptr);
  ASSERT_GE(failing->count(), 1) << "xpbd tunnels at the sweep's fastest balls";
  const int index = mostIsolatedPoint(failing);
  const double parameter = failing->at(index).x();
  mouseClickPoint(view, failing, index);
  ASSERT_GE(runs().runCount(), 1);
  EXPECT_EQ(runs().group().spec(0).backend, "xpbd") << "the circled point opened";
  const auto opened = std::ranges::find_if(dialog->shownPoints(), [&](const auto& point) {
    return point.parameter == parameter &&
           point.scene.balls.size() == runs().group().loadedScene().balls.size() &&
           point.scene.balls.front().velocity ==
               runs().group().loadedScene().balls.front().velocity;
  });
  EXPECT_NE(opened, dialog->shownPoints().end()) << "the scene of the circled point";
}

TEST_F(Tools, OpenedPointRenamesTheChartsRuns) {
  // The charts kept the runs shown before: the legend called chipmunk
  // "box2d:substeps=64,velocity_iterations=2 (reference)".
  open(stillBalls(), "box2d:substeps=64,velocity_iterations=2", {"exact", "xpbd"});
  const QString csvPath = QDir::temp().filePath(QStringLiteral("fooball_opened_names.csv"));
  ASSERT_TRUE(window->scenes().openConfiguration(
      {stillBalls(), QString(), QStringLiteral("test"), RunSpec{"chipmunk", {}}}));
  frames(3);
  ChartPanel* charts = window->charts();
  charts->refresh();
  ASSERT_EQ(charts->runCount(), 2);
  EXPECT_EQ(charts->data().runName(0), QStringLiteral("chipmunk"));
  EXPECT_EQ(charts->data().runName(1), QStringLiteral("exact"));
  // The PNG draws this legend above the charts.
  const QString legend = charts->runLegend().text();
  EXPECT_TRUE(legend.contains(QStringLiteral("chipmunk&nbsp;(reference)"))) << legend.toStdString();
  EXPECT_FALSE(legend.contains(QStringLiteral("box2d"))) << legend.toStdString();
  EXPECT_FALSE(legend.contains(QStringLiteral("xpbd"))) << legend.toStdString();
  ASSERT_TRUE(charts->exportCsv(csvPath));
  QFile csv(csvPath);
  ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
  QSet<QString> runNames;
  csv.readLine();  // the header
  while (!csv.atEnd())
    runNames.insert(QString::fromUtf8(csv.readLine()).section(QLatin1Char(','), 0, 0));
  EXPECT_EQ(runNames, (QSet<QString>{QStringLiteral("chipmunk"), QStringLiteral("exact"),
                                     QStringLiteral("baseline")}));
  csv.remove();
}

TEST_F(Tools, TradeoffLabelsAreWhole) {
  // Before: the trajectory axis' title read "…exact run at 0…", and nine backends' legend
  // entries were shortened.
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  std::vector<measure::TradeoffPoint> points;
  double cost = 1.0;
  for (const BackendInfo& backend : registeredBackends()) {
    for (const int substeps : {1, 4, 16}) {
      measure::TradeoffPoint point;
      point.setting = {std::string(backend.name), {"substeps=" + std::to_string(substeps)}};
      point.cpuMsPerSimulatedSecond = cost *= 1.7;
      point.trajectoryError = 0.3 / substeps;
      point.energyError = 1e-3 / substeps;
      points.push_back(point);
    }
  }
  const measure::TradeoffSettings settings;
  dialog->charts()->showCharts(plots::makeTradeoffCharts(points, settings),
                               plots::tradeoffChartTitle("'gas' (300 balls)", settings));
  expectNothingElided(*dialog, dialog->charts()->views());
}

TEST_F(Tools, BenchmarkLabelsAndTableAreWhole) {
  // Before: the legend read "box2d: 5250…", and the table showed two and a half rows.
  open(stillBalls());
  window->actions().benchmark()->trigger();
  BenchmarkDialog* dialog = window->actions().benchmarkDialog();
  auto* view = dialog->findChild<QChartView*>();
  ASSERT_NE(view, nullptr);
  std::vector<measure::CapacityResult> results;
  QTableWidget* table = dialog->resultsTable();
  for (const BackendInfo& backend : registeredBackends()) {
    measure::CapacityResult result;
    result.backend = backend.name;
    result.outcome.balls = 5250 + 1000 * results.size();
    result.outcome.medianStepMs = 15.0;
    result.outcome.probes = {{1000, 2.0}, {result.outcome.balls, 15.0}};
    results.push_back(result);
    const int row = table->rowCount();
    table->setRowCount(row + 1);
    table->setItem(row, 0, new QTableWidgetItem(QString::fromUtf8(backend.name)));
  }
  QChart* chart = plots::makeCapacityChart(results, measure::CapacitySettings{});
  styleChartDark(*chart);
  delete view->chart();
  view->setChart(chart);
  expectNothingElided(*dialog, {view});
  for (const QSize size : {QSize(1000, 650), QSize(1440, 900)}) {
    dialog->resize(size);
    QCoreApplication::processEvents();
    // All the rows, or whole rows and a scroll bar.
    const int rows = table->verticalHeader()->length();
    const int shown = table->viewport()->height();
    const int rowHeight = table->verticalHeader()->defaultSectionSize();
    EXPECT_TRUE(shown >= rows || shown % rowHeight == 0)
        << "dialog " << dialog->width() << "×" << dialog->height() << ": " << shown
        << " px of table for " << rows << " px of rows";
  }
}

TEST_F(Tools, CancelledTradeoffShowsNoResult) {
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  dialog->presetBox()->setCurrentText(QStringLiteral("gas"));  // every backend: a minute or more
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(
      waitUntil([&] { return dialog->runPanel()->progressBar()->value() > 0; }, 30.0 * slowdown()))
      << "a setting measured before the cancel";
  QTest::mouseClick(dialog->runPanel()->cancelButton(), Qt::LeftButton);
  // It stops after the setting under way: a few seconds at most on the gas.
  ASSERT_TRUE(waitUntil([&] { return !dialog->runPanel()->running(); }, 20.0 * slowdown()));
  expectIdle(dialog);
  EXPECT_TRUE(dialog->points().empty());
  EXPECT_TRUE(dialog->charts()->views().empty()) << "no chart of half a run";
  EXPECT_TRUE(dialog->charts()->placeholder().startsWith(QStringLiteral("Press Start")))
      << "ready for another run";
  EXPECT_EQ(dialog->runPanel()->progressBar()->value(), 0);
  EXPECT_TRUE(dialog->durationEdit()->isEnabled());
}

TEST_F(Tools, TradeoffBadDurationIsOneErrorAndStartsNothing) {
  open(stillBalls());
  TradeoffDialog* dialog = openTradeoff();
  dialog->durationEdit()->setText(QStringLiteral("soon"));
  QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
  EXPECT_FALSE(dialog->runPanel()->running());
  EXPECT_FALSE(runs().paused());
  EXPECT_EQ(dialog->runPanel()->errorLabel()->text(),
            QStringLiteral("duration: must be a number > 0"));
}

TEST_F(Tools, FailureMapRunsAndChartsEachSweep) {
  open(stillBalls());
  FailureMapDialog* dialog = openFailureMap();
  EXPECT_TRUE(dialog->quickBox()->isChecked()) << "quick by default: seconds, not minutes";
  checkOnly(dialog->sweepList(), {QStringLiteral("tunnelling"), QStringLiteral("packing")});
  checkOnly(dialog->backendList(), {QStringLiteral("elastic")});
  runToEnd(dialog);
  expectIdle(dialog);

  const std::vector<failure_map::SweepPoint> tunnelling =
      failure_map::runSweep(failure_map::findSweep("tunnelling"), "elastic", true);
  const std::vector<failure_map::SweepPoint> packing =
      failure_map::runSweep(failure_map::findSweep("packing"), "elastic", true);
  EXPECT_EQ(dialog->points().size(), tunnelling.size() + packing.size());
  EXPECT_EQ(dialog->shownSweepBox()->count(), 2);
  EXPECT_EQ(dialog->shownSweepBox()->currentText(), QStringLiteral("tunnelling"));
  ASSERT_EQ(dialog->charts()->views().size(), 1u) << "tunnelling has no overlap limit";
  QXYSeries* wall =
      seriesNamed(dialog->charts()->views()[0], QStringLiteral("elastic, wall r=0.05 m"));
  ASSERT_NE(wall, nullptr);
  std::vector<double> wallParameters;
  for (const failure_map::SweepPoint& point : tunnelling) {
    if (point.variant == "wall r=0.05 m") wallParameters.push_back(point.parameter);
  }
  ASSERT_EQ(wall->count(), static_cast<int>(wallParameters.size()));
  for (int i = 0; i < wall->count(); ++i)
    EXPECT_EQ(wall->at(i).x(), wallParameters[std::size_t(i)]);

  dialog->shownSweepBox()->setCurrentText(QStringLiteral("packing"));
  EXPECT_EQ(dialog->shownPoints().size(), packing.size());
  EXPECT_EQ(dialog->charts()->views().size(), 2u) << "the error, then the deepest overlap";
}

TEST_F(Tools, FailureMapPointOpensItsSceneAgainstTheReferenceUnlessItIsTheReference) {
  open(stillBalls());
  FailureMapDialog* dialog = openFailureMap();
  checkOnly(dialog->sweepList(), {QStringLiteral("tunnelling")});
  checkOnly(dialog->backendList(), {QStringLiteral("elastic"), QStringLiteral("exact")});
  runToEnd(dialog);
  QChartView* view = dialog->charts()->views().at(0);

  QXYSeries* elastic = seriesNamed(view, QStringLiteral("elastic, ball r=0.05 m"));
  ASSERT_NE(elastic, nullptr);
  const int index = 5;
  clickPoint(dialog, elastic, index);
  const failure_map::SweepPoint* clicked = nullptr;
  for (const failure_map::SweepPoint& point : dialog->shownPoints()) {
    if (point.backend == "elastic" && point.variant == "ball r=0.05 m" &&
        point.parameter == elastic->at(index).x())
      clicked = &point;
  }
  ASSERT_NE(clicked, nullptr);
  ASSERT_EQ(runs().runCount(), 2);
  EXPECT_EQ(runs().group().spec(0), (RunSpec{"elastic", {}}));
  EXPECT_EQ(runs().group().spec(1), (RunSpec{"exact", {}}));
  const Scene& loaded = runs().group().loadedScene();
  EXPECT_EQ(loaded.box, clicked->scene.box);
  ASSERT_EQ(loaded.balls.size(), clicked->scene.balls.size());
  for (std::size_t i = 0; i < loaded.balls.size(); ++i) {
    EXPECT_EQ(loaded.balls[i].position, clicked->scene.balls[i].position);
    EXPECT_EQ(loaded.balls[i].velocity, clicked->scene.balls[i].velocity);
  }

  QXYSeries* exact = seriesNamed(view, QStringLiteral("exact, wall r=0.05 m"));
  ASSERT_NE(exact, nullptr);
  clickPoint(dialog, exact, 0);
  ASSERT_EQ(runs().runCount(), 1) << "the reference is not compared with itself";
  EXPECT_EQ(runs().group().spec(0), (RunSpec{"exact", {}}));
}

TEST_F(Tools, CancelledFailureMapShowsNoResult) {
  open(stillBalls());
  FailureMapDialog* dialog = openFailureMap();
  dialog->quickBox()->setChecked(false);  // every sweep on every backend in full
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(
      waitUntil([&] { return dialog->runPanel()->progressBar()->value() > 0; }, 30.0 * slowdown()))
      << "a sweep finished before the cancel";
  QTest::mouseClick(dialog->runPanel()->cancelButton(), Qt::LeftButton);
  ASSERT_TRUE(waitUntil([&] { return !dialog->runPanel()->running(); }, 20.0 * slowdown()));
  expectIdle(dialog);
  EXPECT_TRUE(dialog->points().empty());
  EXPECT_TRUE(dialog->charts()->views().empty());
  EXPECT_EQ(dialog->shownSweepBox()->count(), 0);
}

TEST_F(Tools, ClosingTheWindowMidRunIsSafe) {
  open(stillBalls());
  TradeoffDialog* tradeoff = openTradeoff();
  FailureMapDialog* failureMap = openFailureMap();
  failureMap->quickBox()->setChecked(false);
  ASSERT_TRUE(tradeoff->start());
  ASSERT_TRUE(failureMap->start());
  EXPECT_TRUE(runs().paused());
  QTest::qWait(50);
  window->close();
  EXPECT_FALSE(tradeoff->isVisible());
  EXPECT_FALSE(failureMap->isVisible());
  window.reset();  // joins the workers
  QCoreApplication::processEvents();
}

// The tools' log axes (shared with fooball-cli's PNGs), as Qt Charts 6.4 draws them: it labels
// every power of the axis' base and elides them all to "…" when they crowd (an energy panel with
// an exact zero error 16 decades below Box2D's did), draws no labels or title at all on an axis
// spanning less than ~1e-11 (elastic and exact alone: errors 4e-16 to 2e-15), and drops the
// bottom label when log10 of the bottom rounds up. So: every k-th decade over many, at most six
// intervals; the top at 1e-11 at least; the bottom a hair below its decade.
TEST(DecadeAxis, KeepsEveryLabelQtWouldDropOrElide) {
  const auto axis = [](double low, double high) {
    return std::unique_ptr<QLogValueAxis>(plots::decadeAxis(QString(), low, high, "%.0e"));
  };
  const auto expectRange = [](const QLogValueAxis& shown, double bottom, double top) {
    EXPECT_LT(shown.min(), bottom) << "a hair below the bottom decade";
    EXPECT_GT(shown.min(), bottom * (1.0 - 1e-6));
    EXPECT_EQ(shown.max(), top);
  };
  const auto wide = axis(3e-17, 0.02);  // decades -17 to -1: 16, so every third from -18 to 0
  EXPECT_EQ(wide->base(), 1000.0);
  expectRange(*wide, 1e-18, 1.0);
  EXPECT_EQ(wide->minorTickCount(), 0);
  const auto six = axis(1e-4, 50.0);  // -4 to 2: six decades, each labelled
  EXPECT_EQ(six->base(), 10.0);
  expectRange(*six, 1e-4, 100.0);
  const auto narrow = axis(2.0, 5.0);  // within one decade: 1 to 10, with the 2…9 lines
  EXPECT_EQ(narrow->base(), 10.0);
  expectRange(*narrow, 1.0, 10.0);
  EXPECT_EQ(narrow->minorTickCount(), 8);
  const auto tiny = axis(4e-17, 2e-15);  // up to 1e-11, where Qt draws the labels again
  EXPECT_EQ(tiny->base(), 10.0);
  expectRange(*tiny, 1e-17, 1e-11);
  const auto none = axis(0.0, 0.0);  // nothing a log axis can show: one decade from 1
  expectRange(*none, 1.0, 10.0);
}

}  // namespace
}  // namespace fooball::gui::testing
