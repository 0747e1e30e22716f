#include "tools/benchmark_dialog.h"

#include <QChart>
#include <QChartView>
#include <QElapsedTimer>
#include <QFile>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <algorithm>
#include <functional>

#include "gui_fixture.h"
#include "sidebar/run_list_editor.h"
#include "tools/tool_run_panel.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

class Benchmark : public GuiTest {
 protected:
  BenchmarkDialog* openDialog() {
    window->actions().benchmark()->trigger();
    return window->actions().benchmarkDialog();
  }

  /// Only `backend` checked, the budget `budgetMs`.
  void choose(BenchmarkDialog* dialog, const QString& backend, const QString& budgetMs) {
    QListWidget* list = dialog->backendList();
    for (int row = 0; row < list->count(); ++row) {
      QListWidgetItem* item = list->item(row);
      item->setCheckState(backend.isEmpty() || item->text() == backend ? Qt::Checked
                                                                       : Qt::Unchecked);
    }
    dialog->budgetEdit()->setText(budgetMs);
  }
};

/// Whether every column header's text fits its section as drawn (the header once read
/// "nedian step (ms": centred and cut at both ends).
void expectHeadersFit(const QTableWidget& table, const std::string& when) {
  const QHeaderView* header = table.horizontalHeader();
  const QFontMetrics metrics(header->font());
  for (int column = 0; column < table.columnCount(); ++column) {
    const QString text = table.horizontalHeaderItem(column)->text();
    // The style's margins on both sides of the text, as a section's size hint counts them.
    const int needed = metrics.horizontalAdvance(text) + 8;
    EXPECT_GE(header->sectionSize(column), needed) << when << ": " << text.toStdString();
  }
  int total = 0;
  for (int column = 0; column < table.columnCount(); ++column)
    total += header->sectionSize(column);
  EXPECT_LE(total, header->width() + 1) << when << ": the last column runs out of the table";
}

TEST_F(Benchmark, ColumnHeadersFitBeforeAndAfterARun) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  QCoreApplication::processEvents();
  expectHeadersFit(*dialog->resultsTable(), "before a run");
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("0.05"));
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 20.0 * slowdown()));
  QCoreApplication::processEvents();
  expectHeadersFit(*dialog->resultsTable(), "after a run");
}

TEST_F(Benchmark, ChartShowsEachCountAsItIsMeasured) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  // Nothing measured yet: no empty 1–10 axes, a title that says what will come.
  for (const QAbstractAxis* axis : dialog->chartView()->chart()->axes())
    EXPECT_FALSE(axis->isVisible());
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("1000"));
  ASSERT_TRUE(dialog->start());
  const auto measuredPoints = [&] {
    int points = 0;
    for (const QAbstractSeries* series : dialog->chartView()->chart()->series()) {
      if (const auto* line = qobject_cast<const QLineSeries*>(series);
          line != nullptr && line->name().startsWith(QStringLiteral("elastic")))
        points += line->count();
    }
    return points;
  };
  ASSERT_TRUE(waitUntil([&] { return measuredPoints() >= 1; }, 20.0 * slowdown()))
      << "the chart shows nothing while the search runs";
  EXPECT_TRUE(dialog->running());
  for (const QAbstractAxis* axis : dialog->chartView()->chart()->axes())
    EXPECT_TRUE(axis->isVisible());
  dialog->runPanel()->cancel();
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 10.0 * slowdown()));
}

TEST_F(Benchmark, CancelledRunAddsNoResult) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  // One backend with a budget it never reaches: the search is still going when cancelled.
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("1000"));
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(
      waitUntil([&] { return dialog->runPanel()->progressBar()->value() > 0; }, 20.0 * slowdown()));
  dialog->runPanel()->cancel();
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 10.0 * slowdown()));
  EXPECT_TRUE(dialog->results().empty());
  EXPECT_EQ(dialog->resultsTable()->rowCount(), 0);
  for (const QAbstractAxis* axis : dialog->chartView()->chart()->axes())
    EXPECT_FALSE(axis->isVisible()) << "no result: no empty axes either";
}

TEST_F(Benchmark, ToolsMenuOpensTheDialog) {
  open(stillBalls());
  bool inToolsMenu = false;
  for (QAction* menu : window->menuBar()->actions()) {
    if (menu->text() == QStringLiteral("&Tools") && menu->menu())
      inToolsMenu = menu->menu()->actions().contains(window->actions().benchmark());
  }
  EXPECT_TRUE(inToolsMenu);
  EXPECT_EQ(window->actions().benchmarkDialog(), nullptr);
  BenchmarkDialog* dialog = openDialog();
  ASSERT_NE(dialog, nullptr);
  EXPECT_TRUE(dialog->isVisible());
  EXPECT_EQ(dialog->backendList()->count(), static_cast<int>(registeredBackends().size()));
  for (int row = 0; row < dialog->backendList()->count(); ++row)
    EXPECT_EQ(dialog->backendList()->item(row)->checkState(), Qt::Checked) << "all by default";
  EXPECT_EQ(dialog->budgetEdit()->text(), QStringLiteral("16.67"));
  EXPECT_FALSE(dialog->runPanel()->cancelButton()->isEnabled());
}

TEST_F(Benchmark, TinyBudgetRunGivesACapacityWithoutBlockingTheWindow) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  // 4 ms: tens of thousands of balls, found in about a second of wall time in any build (each
  // probe near the budget takes ten steps of ~4 ms), so the event loop comes round many times
  // while the search runs even on a loaded machine that deschedules the GUI thread for a while.
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("4"));

  // A heartbeat of posted events on the GUI thread: it beats during the run only if the search
  // runs elsewhere. Posted events, not a zero-interval QTimer: Qt's glib event dispatcher runs
  // timers at idle priority once one has fired, and the worker's progress events can starve it.
  int beatsDuringRun = 0;
  bool beating = true;
  std::function<void()> beat = [&] {
    if (!beating) return;
    if (dialog->running()) ++beatsDuringRun;
    QMetaObject::invokeMethod(dialog, beat, Qt::QueuedConnection);
  };
  QMetaObject::invokeMethod(dialog, beat, Qt::QueuedConnection);

  QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
  EXPECT_TRUE(dialog->running()) << "Start returned before the search ended";
  EXPECT_TRUE(runs().paused()) << "the simulation pauses while the benchmark measures";
  EXPECT_TRUE(dialog->runPanel()->cancelButton()->isEnabled());
  EXPECT_FALSE(dialog->runPanel()->startButton()->isEnabled());
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 20.0 * slowdown()));
  beating = false;
  QCoreApplication::processEvents();  // the last beat sees `beating` off and posts no more

  EXPECT_GT(beatsDuringRun, 1) << "the event loop ran while the search did";
  EXPECT_FALSE(runs().paused()) << "the simulation continues after the run";
  EXPECT_EQ(dialog->runPanel()->progressBar()->value(),
            dialog->runPanel()->progressBar()->maximum());
  ASSERT_EQ(dialog->results().size(), 1u);
  EXPECT_EQ(dialog->results()[0].backend, "elastic");
  EXPECT_GT(dialog->results()[0].outcome.balls, 0u);
  EXPECT_LE(dialog->results()[0].outcome.medianStepMs, 4.0);
  ASSERT_EQ(dialog->resultsTable()->rowCount(), 1);
  EXPECT_EQ(dialog->resultsTable()->item(0, 0)->text(), QStringLiteral("elastic"));
  EXPECT_EQ(dialog->resultsTable()->item(0, 1)->text().toULongLong(),
            dialog->results()[0].outcome.balls);
  EXPECT_TRUE(dialog->runPanel()->errorLabel()->isHidden());

  const QTemporaryDir directory;
  const QString csvPath = directory.filePath(QStringLiteral("capacity.csv"));
  ASSERT_TRUE(dialog->saveCsv(csvPath));
  QFile csv(csvPath);
  ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
  const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
  ASSERT_EQ(lines.size(), 2);
  EXPECT_EQ(lines[0], QStringLiteral("backend,balls,median_step_ms"));
  EXPECT_TRUE(
      lines[1].startsWith(QStringLiteral("elastic,%1,").arg(dialog->results()[0].outcome.balls)))
      << lines[1].toStdString();

  const QString pngPath = directory.filePath(QStringLiteral("capacity.png"));
  ASSERT_TRUE(dialog->savePng(pngPath));
  const QImage image(pngPath);
  EXPECT_GT(image.width(), 100);
  EXPECT_GT(image.height(), 100);
}

TEST_F(Benchmark, AnEngineInNodeJsSaysWhatItRunsAsBesideItsCapacity) {
  // matter.js is JavaScript: its capacity is not a native engine's, and the table says so.
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  choose(dialog, QStringLiteral("matter"), QStringLiteral("4"));
  QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 60.0 * slowdown()));
  ASSERT_EQ(dialog->resultsTable()->rowCount(), 1);
  EXPECT_EQ(dialog->resultsTable()->item(0, 0)->text(), QStringLiteral("matter"));
  EXPECT_GT(dialog->resultsTable()->item(0, 1)->text().toULongLong(), 0u);
  EXPECT_TRUE(dialog->resultsTable()->item(0, 3)->text().startsWith(
      QStringLiteral("JavaScript in Node.js")))
      << dialog->resultsTable()->item(0, 3)->text().toStdString();
}

TEST_F(Benchmark, PausedSimulationStaysPausedAfterARun) {
  open(stillBalls());
  runs().setPaused(true);
  BenchmarkDialog* dialog = openDialog();
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("0.05"));
  ASSERT_TRUE(dialog->start());
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 20.0 * slowdown()));
  EXPECT_TRUE(runs().paused());
}

TEST_F(Benchmark, CancelStopsALongRunPromptly) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  // A second per step and every backend: minutes if it were not cancelled.
  choose(dialog, QString(), QStringLiteral("1000"));
  ASSERT_TRUE(dialog->start());
  // Let it measure a count or two first.
  waitUntil([&] { return dialog->runPanel()->progressBar()->value() > 0; }, 2.0);
  QElapsedTimer clock;
  clock.start();
  QTest::mouseClick(dialog->runPanel()->cancelButton(), Qt::LeftButton);
  // The search checks for a stop every step; the largest step of the first seconds of the
  // search is far below this bound.
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 10.0 * slowdown()));
  EXPECT_LT(double(clock.elapsed()), 10'000.0 * slowdown());
  EXPECT_LT(dialog->results().size(), registeredBackends().size());
  EXPECT_FALSE(runs().paused());
  EXPECT_TRUE(dialog->runPanel()->startButton()->isEnabled()) << "ready for another run";
}

TEST_F(Benchmark, ClosingTheDialogMidRunCancelsIt) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  choose(dialog, QString(), QStringLiteral("1000"));
  ASSERT_TRUE(dialog->start());
  QTest::qWait(50);
  dialog->close();  // returns once the worker has stopped and joined
  EXPECT_FALSE(dialog->isVisible());
  ASSERT_TRUE(waitUntil([&] { return !dialog->running(); }, 1.0));
  EXPECT_FALSE(runs().paused());
}

TEST_F(Benchmark, ClosingTheWindowMidRunIsSafe) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  choose(dialog, QString(), QStringLiteral("1000"));
  ASSERT_TRUE(dialog->start());
  QTest::qWait(50);
  window->close();
  EXPECT_FALSE(dialog->isVisible()) << "the dialog closes with the window";
  window.reset();  // joins the worker; ASan would report a use after free or a leak
  QCoreApplication::processEvents();  // events the worker posted go with the dialog
}

TEST_F(Benchmark, BadBudgetShowsOneErrorAndStartsNothing) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  for (const QString& budget : {QStringLiteral("0"), QStringLiteral("-2"), QStringLiteral("nan"),
                                QStringLiteral("fast"), QString()}) {
    choose(dialog, QStringLiteral("elastic"), budget);
    QTest::mouseClick(dialog->runPanel()->startButton(), Qt::LeftButton);
    EXPECT_FALSE(dialog->running()) << budget.toStdString();
    EXPECT_FALSE(runs().paused());
    EXPECT_FALSE(dialog->runPanel()->errorLabel()->isHidden());
    EXPECT_EQ(dialog->runPanel()->errorLabel()->text(),
              QStringLiteral("budget: must be a number > 0"))
        << budget.toStdString();
  }
}

TEST_F(Benchmark, UnknownOptionAndNoBackendAreErrors) {
  open(stillBalls());
  BenchmarkDialog* dialog = openDialog();
  choose(dialog, QStringLiteral("elastic"), QStringLiteral("1"));
  dialog->optionsEdit()->setText(QStringLiteral("warp=9"));
  EXPECT_FALSE(dialog->start());
  EXPECT_TRUE(dialog->runPanel()->errorLabel()->text().contains(QStringLiteral("warp")));
  dialog->optionsEdit()->clear();
  choose(dialog, QStringLiteral("no such backend"), QStringLiteral("1"));
  EXPECT_FALSE(dialog->start());
  EXPECT_TRUE(dialog->runPanel()->errorLabel()->text().contains(QStringLiteral("backends")));
}

}  // namespace
}  // namespace fooball::gui::testing
