// Compare mode through the sidebar's run list, as a user drives it: adding, removing and
// switching runs, the chaos baseline, and what the readout and the charts then hold.

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolButton>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "control/scene_session.h"
#include "fooball/number_text.h"
#include "frames/run_feed.h"
#include "gui_fixture.h"
#include "readouts/compare_readout.h"
#include "readouts/run_counters.h"
#include "sidebar/backend_options_form.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "window/headless_run.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

class CompareMode : public GuiTest {
 protected:
  RunListEditor* runList() const { return window->sidebar()->runList(); }

  /// Chooses `backend` for the new run and clicks Add run, as a user would.
  void addRun(const QString& backend) {
    QComboBox* box = runList()->newRunBackendBox();
    const int index = box->findText(backend);
    ASSERT_GE(index, 0) << backend.toStdString();
    box->setCurrentIndex(index);
    QTest::mouseClick(runList()->addButton(), Qt::LeftButton);
  }
};

TEST_F(CompareMode, AddingARunRestartsEveryRunFromTheCurrentStateAndTimeCarriesOn) {
  open(fooball::testing::gas(50));
  frames(20);
  const Scene now = mainRun().scene();
  const double time = group().time();
  ASSERT_GT(time, 0.0);
  addRun(QStringLiteral("box2d"));
  ASSERT_EQ(runs().runCount(), 2);
  EXPECT_EQ(runs().label(1), QStringLiteral("box2d"));
  EXPECT_TRUE(window->compareReadout()->isVisible());
  for (std::size_t i = 0; i < now.balls.size(); ++i) {
    EXPECT_EQ(runs().run(0).positions()[i], now.balls[i].position);
    // Box2D holds float: 16 m to within half a float ulp, 1e-6 m.
    EXPECT_NEAR(runs().run(1).positions()[i].x, now.balls[i].position.x, 1e-5);
  }
  EXPECT_EQ(runs().run(0).time(), time) << "the clock carries on";
  EXPECT_EQ(runs().run(1).time(), time);
  EXPECT_GT(markerCount(*window->charts()), 0) << "the restart is marked on the time axis";
  frames(30);
  EXPECT_EQ(runs().run(0).steps(), runs().run(1).steps());
  EXPECT_GT(runs().run(0).steps(), 0u);
}

TEST_F(CompareMode, SameSpecStaysIdenticalAndTheBaselineDepartsFromIt) {
  open(fooball::testing::gas(200), "elastic", {"elastic"});
  ASSERT_TRUE(group().hasBaseline()) << "compare mode shows the chaos baseline by default";
  EXPECT_TRUE(runList()->baselineBox()->isChecked());
  const double start = group().baselineDivergence()->rmsPositionDifference;
  EXPECT_NEAR(start, RunGroup::kBaselineDisplacement, 1e-12);
  frames(180);
  const Divergence same = group().divergence(1);
  EXPECT_EQ(same.maxPositionDifference, 0.0) << "deterministic backends";
  EXPECT_EQ(same.energyDifference, 0.0);
  // A 200-ball gas is chaotic: 3 s amplify 1e-9 m by far more than a factor of 10.
  EXPECT_GT(group().baselineDivergence()->rmsPositionDifference, 10.0 * start);
}

/// One row of the readout as numbers: "box2d: RMS 0.0123 m, max 0.0456 m, energy +1.2e-05 J
/// (+0.0001 %), momentum 3.4e-06 N·s".
struct ReadoutRow {
  QString label;
  double rms = std::nan("");            ///< m
  double max = std::nan("");            ///< m
  double energy = std::nan("");         ///< J
  double energyPercent = std::nan("");  ///< % of run 0's energy
  double momentum = std::nan("");       ///< N·s
};

/// The readout's rows after its first line (which names run 0), as a user reads them.
std::vector<ReadoutRow> readoutRows(const CompareReadout& readout) {
  static const QRegularExpression row(QStringLiteral(
      "^(.+): RMS (\\S+) m, max (\\S+) m, energy (\\S+) J \\((\\S+) %\\), momentum (\\S+) N·s$"));
  std::vector<ReadoutRow> rows;
  const QStringList lines = readout.text().split(QLatin1Char('\n'));
  for (qsizetype i = 1; i < lines.size(); ++i) {
    const QRegularExpressionMatch match = row.match(lines[i]);
    EXPECT_TRUE(match.hasMatch()) << lines[i].toStdString();
    if (!match.hasMatch()) continue;
    const auto number = [&](int group) {
      bool ok = false;
      const double value = match.captured(group).toDouble(&ok);
      EXPECT_TRUE(ok) << "'" << match.captured(group).toStdString() << "' in "
                      << lines[i].toStdString();
      return value;
    };
    rows.push_back({match.captured(1), number(2), number(3), number(4), number(5), number(6)});
  }
  return rows;
}

/// `shown` is `value` to the digits the readout prints (4 significant, or 3 in exponent form).
void expectFigure(double shown, double value, const std::string& what) {
  EXPECT_NEAR(shown, value, 5e-3 * std::abs(value)) << what;
}

/// The moment the readout's first line names ("… (run 0) at t = 4.90 s"), in s; NaN if none.
double readoutTime(const CompareReadout& readout) {
  static const QRegularExpression moment(QStringLiteral(" at t = (\\S+) s$"));
  const QRegularExpressionMatch match =
      moment.match(readout.text().split(QLatin1Char('\n')).front());
  bool ok = false;
  const double time = match.hasMatch() ? match.captured(1).toDouble(&ok) : 0.0;
  return ok ? time : std::nan("");
}

/// Every run's divergence from run 0 (index = run index) and the baseline's at one moment, each
/// measured on its own as `fooball-cli compare` measures its rows.
struct Moment {
  std::vector<Divergence> fromRunZero;
  std::optional<Divergence> baseline;
};

Moment momentOf(const RunGroup& group) {
  Moment moment;
  for (std::size_t i = 0; i < group.runCount(); ++i)
    moment.fromRunZero.push_back(group.divergence(i));
  moment.baseline = group.baselineDivergence();
  return moment;
}

/// Every figure of every row of the readout is `expected`'s divergence of that run from run 0
/// (and the baseline's), to the digits shown, and the rows name the runs in order.
void expectReadoutShows(const CompareReadout& readout, const RunController& runs,
                        const Moment& expected, const std::string& when) {
  const std::vector<ReadoutRow> rows = readoutRows(readout);
  const std::size_t runRows = expected.fromRunZero.size() - 1;
  ASSERT_EQ(rows.size(), runRows + (expected.baseline ? 1 : 0))
      << when << ": " << readout.text().toStdString();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool baseline = i == runRows;
    const Divergence divergence = baseline ? *expected.baseline : expected.fromRunZero[i + 1];
    const std::string what = std::string(when) + ", row " + rows[i].label.toStdString();
    EXPECT_EQ(rows[i].label,
              baseline ? QStringLiteral("chaos baseline") : runs.label(static_cast<int>(i + 1)))
        << what;
    expectFigure(rows[i].rms, divergence.rmsPositionDifference, what + " RMS");
    expectFigure(rows[i].max, divergence.maxPositionDifference, what + " max");
    expectFigure(rows[i].energy, divergence.energyDifference, what + " energy");
    expectFigure(rows[i].energyPercent, 100.0 * divergence.relativeEnergyDifference,
                 what + " energy %");
    expectFigure(rows[i].momentum, divergence.momentumDifference, what + " momentum");
  }
}

/// The readout shows the run group's figures of now, and says so.
void expectReadoutShows(const CompareReadout& readout, const RunController& runs,
                        const char* when) {
  expectReadoutShows(readout, runs, momentOf(runs.group()), when);
  EXPECT_NEAR(readoutTime(readout), runs.group().time(), 0.005)
      << when << ": " << readout.text().toStdString();
}

TEST_F(CompareMode, TheReadoutShowsTheRunGroupsOwnDivergenceNumbers) {
  open(fooball::testing::gas(80), "elastic", {"box2d", "exact"});
  ASSERT_TRUE(group().hasBaseline());
  frames(120);
  window->feed().showReadouts();
  const Divergence divergence = group().divergence(1);
  EXPECT_GT(divergence.maxPositionDifference, 0.0);
  EXPECT_LE(divergence.rmsPositionDifference, divergence.maxPositionDifference);
  EXPECT_NE(group().divergence(1).energyDifference, 0.0) << "Box2D's energy differs: a figure";
  expectReadoutShows(*window->compareReadout(), runs(), "after 2 s");
}

TEST_F(CompareMode, TheReadoutFollowsRestartAndSingleStepsWhilePaused) {
  open(fooball::testing::gas(80), "elastic", {"box2d"});
  frames(120);
  window->actions().pause()->trigger();
  ASSERT_TRUE(runs().paused());
  const double before = group().divergence(1).rmsPositionDifference;
  expectReadoutShows(*window->compareReadout(), runs(), "paused");

  window->session().restart();
  const double restarted = group().divergence(1).rmsPositionDifference;
  ASSERT_LT(restarted, 1e-3 * before) << "at t = 0 only Box2D's float rounding differs";
  expectReadoutShows(*window->compareReadout(), runs(), "after Restart");

  for (int step = 0; step < 3; ++step) {
    window->actions().step()->trigger();
    expectReadoutShows(*window->compareReadout(), runs(), "after Single step");
  }
  EXPECT_NE(group().divergence(1).rmsPositionDifference, restarted) << "the steps moved the runs";
}

TEST_F(CompareMode, PausingShowsTheReadoutOfTheStatePausedOn) {
  open(fooball::testing::gas(80), "elastic", {"box2d"});
  frames(121);  // the readout refreshes every 6 frames: its last refresh is a frame old
  window->actions().pause()->trigger();
  expectReadoutShows(*window->compareReadout(), runs(), "paused after 121 frames");
}

TEST_F(CompareMode, TheReadoutSaysItsMomentAndEveryFigureIsOfThatMoment) {
  // While the runs step, the readout refreshes a few times a second from the state before a
  // frame's steps: whatever moment it shows, it names it, and all its figures are of it.
  open(fooball::testing::gas(80), "elastic", {"box2d", "exact"});
  ASSERT_TRUE(group().hasBaseline());
  std::map<double, Moment> moments;  // by simulated time, after every frame
  moments[group().time()] = momentOf(group());
  for (int frame = 0; frame < 125; ++frame) {
    frames(1);
    moments[group().time()] = momentOf(group());
  }
  const double shown = readoutTime(*window->compareReadout());
  ASSERT_FALSE(std::isnan(shown)) << window->compareReadout()->text().toStdString();
  // The readout's time has two decimals; frames are 1/60 s apart: one moment within 0.005 s.
  const auto at = moments.lower_bound(shown - 0.005);
  ASSERT_TRUE(at != moments.end() && at->first < shown + 0.005) << shown;
  EXPECT_LE(at->first, group().time());
  EXPECT_GT(at->first, group().time() - 7 * kFrame) << "a refresh comes every 6 frames";
  expectReadoutShows(*window->compareReadout(), runs(), at->second,
                     "at the t = " + std::to_string(shown) + " s the readout names");
  // The figures move between frames, so a readout of another moment would be caught.
  const Moment& earlier = std::prev(at)->second;
  EXPECT_NE(earlier.fromRunZero[1].rmsPositionDifference,
            at->second.fromRunZero[1].rmsPositionDifference);
}

TEST_F(CompareMode, AScreenshotShowsTheReadoutOfTheMomentTheStatusBarShows) {
  // `fooball --frames 300 --screenshot`: the status bar says t = 5.00 s, and so must the readout,
  // with 5.00 s's figures (it showed those of 4.90 s, its last refresh, 6 frames before).
  open(fooball::testing::gas(80), "elastic", {"box2d"});
  QTemporaryDir directory;
  ASSERT_EQ(
      runHeadless(*window, 300, directory.filePath(QStringLiteral("shot.png")), QSize(1280, 800)),
      0);
  ASSERT_NEAR(group().time(), 5.0, 1e-9);
  expectReadoutShows(*window->compareReadout(), runs(), "in the screenshot after 300 frames");
}

/// What one run (or the baseline) was at a moment: its metrics and its divergence from run 0.
struct RunState {
  Metrics metrics;
  Divergence divergence;
};

/// A curve of the charts and the number it plots from a run's state.
struct PlottedQuantity {
  int chart;
  int curve;
  double (*value)(const RunState&);
  const char* name;
};

constexpr PlottedQuantity kPlotted[] = {
    {ChartPanel::kMomentumChart, 0, [](const RunState& s) { return s.metrics.sums.momentum.x; },
     "px"},
    {ChartPanel::kMomentumChart, 1, [](const RunState& s) { return s.metrics.sums.momentum.y; },
     "py"},
    {ChartPanel::kMomentumChart, 2,
     [](const RunState& s) {
       return std::hypot(s.metrics.sums.momentum.x, s.metrics.sums.momentum.y);
     },
     "|p|"},
    {ChartPanel::kEnergyChart, 0, [](const RunState& s) { return s.metrics.sums.kineticEnergy; },
     "kinetic"},
    {ChartPanel::kEnergyChart, 1, [](const RunState& s) { return s.metrics.sums.potentialEnergy; },
     "potential"},
    {ChartPanel::kEnergyChart, 2, [](const RunState& s) { return s.metrics.sums.totalEnergy(); },
     "total"},
    {ChartPanel::kResidualChart, 0, [](const RunState& s) { return s.metrics.energyResidual; },
     "residual"},
    {ChartPanel::kDivergenceChart, 0,
     [](const RunState& s) { return s.divergence.rmsPositionDifference; }, "divergence"},
};

TEST_F(CompareMode, TheChartsPlotEveryRunsMetricsAndTheirTicksReadThem) {
  Scene scene = fooball::testing::gas(60);
  scene.world.gravity = {0.0, -9.81};  // potential energy and a residual that are not all 0
  open(scene, "elastic", {"box2d", "exact"});
  ASSERT_TRUE(group().hasBaseline());
  const int runCount = runs().runCount();
  // Every run's state after every frame, by simulated time (the charts sample some of them);
  // index runCount holds the baseline's.
  std::map<double, std::vector<RunState>> states;
  const auto record = [&] {
    std::vector<RunState>& at = states[group().time()];
    at.clear();
    for (int run = 0; run < runCount; ++run)
      at.push_back({group().run(std::size_t(run)).metrics(), group().divergence(std::size_t(run))});
    at.push_back({group().baseline()->metrics(), *group().baselineDivergence()});
  };
  record();
  for (int frame = 0; frame < 90; ++frame) {
    frames(1);
    record();
  }
  ChartPanel& charts = *window->charts();
  charts.refresh();
  QApplication::processEvents();  // Qt Charts lays out its labels then

  std::array<std::pair<double, double>, ChartPanel::kChartCount> plotted;
  plotted.fill({HUGE_VAL, -HUGE_VAL});
  for (const PlottedQuantity& quantity : kPlotted) {
    const bool divergence = quantity.chart == ChartPanel::kDivergenceChart;
    const double factor = titleFactor(displayedValueAxisTitle(charts, quantity.chart));
    for (int run = 0; run <= runCount; ++run) {
      const int index = run == runCount ? ChartPanel::kBaselineRun : run;
      const QList<QPointF> points = displayedPoints(charts, quantity.chart, index, quantity.curve);
      const std::string what =
          std::string(quantity.name) + " of " +
          (run == runCount ? std::string("the baseline") : runs().label(run).toStdString());
      // Run 0 has no divergence from itself; the baseline has only its divergence.
      if (divergence ? run == 0 : run == runCount) {
        EXPECT_TRUE(points.isEmpty()) << what;
        continue;
      }
      ASSERT_GE(points.size(), 25) << what << ": 90 frames, a sample every few";
      for (const QPointF& point : points) {
        const auto at = states.find(point.x());
        ASSERT_NE(at, states.end()) << what << ": no state at t = " << point.x();
        const double value = quantity.value(at->second[std::size_t(run)]);
        EXPECT_NEAR(point.y() * factor, value, 4e-16 * std::abs(value))
            << what << " at t = " << point.x();
        plotted[quantity.chart] = {std::min(plotted[quantity.chart].first, value),
                                   std::max(plotted[quantity.chart].second, value)};
      }
    }
  }
  for (int chart = 0; chart < ChartPanel::kChartCount; ++chart) {
    expectTicksReadTheData(displayedValueTickLabels(charts, chart),
                           displayedValueAxisTitle(charts, chart), plotted[chart].first,
                           plotted[chart].second, chart == ChartPanel::kDivergenceChart,
                           "chart " + std::to_string(chart));
  }
}

TEST_F(CompareMode, TheCountersSayHowManyBallsABackendHoldsAtRest) {
  // One ball rolling on the floor under gravity: exact lays it to rest on the floor (its
  // normal motion held by the wall), elastic holds nothing at rest.
  Scene scene = fooball::testing::emptyBox();
  scene.world.gravity = {0.0, -9.81};
  scene.balls = {fooball::testing::ball({2.0, 0.5}, {1.5, 0.0})};
  open(scene, "exact", {"elastic"});
  frames(30);
  window->feed().showReadouts();
  ASSERT_EQ(runs().run(0).metrics().restingBalls, 1u);
  ASSERT_EQ(runs().run(1).metrics().restingBalls, 0u);
  const QStringList lines = window->sidebar()->counters()->text().split(QLatin1Char('\n'));
  ASSERT_EQ(lines.size(), 2);
  EXPECT_TRUE(lines[0].endsWith(QStringLiteral(", 1 resting"))) << lines[0].toStdString();
  EXPECT_FALSE(lines[1].contains(QStringLiteral("resting"))) << lines[1].toStdString();
}

TEST_F(CompareMode, TheCountersShowEachRunsOwnCollisionsBouncesOverlapAndEscapes) {
  open(fooball::testing::gas(80), "elastic", {"exact", "box2d"});
  frames(90);
  window->feed().showReadouts();
  const QStringList lines = window->sidebar()->counters()->text().split(QLatin1Char('\n'));
  ASSERT_EQ(lines.size(), 3) << window->sidebar()->counters()->text().toStdString();
  const QRegularExpression row(QStringLiteral(
      "^(.+): ([0-9,]+) ball–ball, ([0-9,]+) wall, overlap (.+), ([0-9,]+) escaped$"));
  for (int run = 0; run < 3; ++run) {
    const Metrics metrics = runs().run(run).metrics();
    const QRegularExpressionMatch match = row.match(lines[run]);
    ASSERT_TRUE(match.hasMatch()) << lines[run].toStdString();
    const auto count = [&](int group) {
      return match.captured(group).remove(QLatin1Char(',')).toULongLong();
    };
    EXPECT_EQ(match.captured(1), runs().label(run));
    EXPECT_GT(metrics.ballCollisions, 0u) << "80 balls in 1.5 s collide";
    EXPECT_EQ(count(2), metrics.ballCollisions) << lines[run].toStdString();
    EXPECT_EQ(count(3), metrics.wallCollisions) << lines[run].toStdString();
    EXPECT_EQ(count(5), metrics.escaped) << lines[run].toStdString();
    const QString overlap = match.captured(4);
    const double shown = overlap == QStringLiteral("0")
                             ? 0.0
                             : overlap.section(QLatin1Char(' '), 0, 0).toDouble() / 100.0;
    EXPECT_NEAR(shown, metrics.maxOverlap, 0.05 * metrics.maxOverlap) << lines[run].toStdString();
  }
}

TEST_F(CompareMode, TheCountersShowAnOverlapDeeperThanTheRadiusInWholePercents) {
  // Two balls of radius 0.1 m, centres 0.4 m apart, close at 20 m/s. Box2D finds no contact at the
  // step's start and does not sweep ball pairs, so one 1/60 s Box2D step leaves their centres
  // 0.4 − 20/60 = 0.067 m apart: an overlap of 133 % of the radius, as beyond its limits.
  Scene scene = fooball::testing::emptyBox();
  scene.balls = {fooball::testing::ball({7.8, 4.5}, {10.0, 0.0}, 0.1),
                 fooball::testing::ball({8.2, 4.5}, {-10.0, 0.0}, 0.1)};
  open(scene, "box2d:substeps=1");
  frames(1);
  window->feed().showReadouts();
  const double overlap = runs().run(0).metrics().maxOverlap;
  // Box2D works in single precision: its positions round at ~1e-6 m.
  ASSERT_NEAR(overlap, (0.2 - (0.4 - 20.0 / 60.0)) / 0.1, 1e-4) << "the balls passed inwards";
  const QRegularExpressionMatch shown = QRegularExpression(QStringLiteral("overlap ([0-9,]+) %,"))
                                            .match(window->sidebar()->counters()->text());
  ASSERT_TRUE(shown.hasMatch()) << window->sidebar()->counters()->text().toStdString();
  EXPECT_EQ(shown.captured(1).remove(QLatin1Char(',')).toInt(), std::lround(100.0 * overlap));
}

TEST_F(CompareMode, OptionsReadAsWordsAndShowTinyValuesAndWholeNumbersExactly) {
  open(fooball::testing::gas(30), "exact", {"box2d"});
  BackendOptionsForm* exact = runList()->optionsForm(0);
  auto* restBounce = exact->findChild<QDoubleSpinBox*>(QStringLiteral("option_rest_bounce_time"));
  ASSERT_NE(restBounce, nullptr);
  const double restBounceTime = runs().run(0).backend().options().value("rest_bounce_time");
  ASSERT_GT(restBounceTime, 0.0);
  ASSERT_LT(restBounceTime, 1e-3);
  EXPECT_EQ(restBounce->text(), QString::fromStdString(exactNumberText(restBounceTime)))
      << "a tiny default reads as itself, not 0.0000";
  // The user types another tiny value in exponent form.
  restBounce->selectAll();
  QTest::keyClicks(restBounce, QStringLiteral("2e-05"));
  QTest::keyClick(restBounce, Qt::Key_Return);
  EXPECT_EQ(runs().run(0).backend().options().value("rest_bounce_time"), 2e-5);

  // Labels are words; the key is in the tooltip.
  BackendOptionsForm* box2d = runList()->optionsForm(1);
  auto* iterations = box2d->findChild<QSpinBox*>(QStringLiteral("option_velocity_iterations"));
  ASSERT_NE(iterations, nullptr);
  QLabel* label = nullptr;
  for (QLabel* candidate : box2d->findChildren<QLabel*>()) {
    if (candidate->buddy() == iterations) label = candidate;
  }
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->text(), QStringLiteral("Velocity iterations:"));
  EXPECT_TRUE(label->toolTip().contains(QStringLiteral("velocity_iterations")));
  // A whole-number option's chart marker reads as a whole number.
  iterations->setValue(12);
  const QStringList markers = markerLabels(*window->charts());
  ASSERT_FALSE(markers.empty());
  EXPECT_EQ(markers.back(), QStringLiteral("velocity_iterations = 12"));
}

TEST_F(CompareMode, AnOptionWithNamedValuesIsADropDownOfThemAndSetsTheRunsEngine) {
  // Rapier's releases: the form lists them by name; choosing one sets that run's option.
  open(fooball::testing::gas(30), "elastic", {"rapier"});
  auto* version =
      runList()->optionsForm(1)->findChild<QComboBox*>(QStringLiteral("option_version"));
  ASSERT_NE(version, nullptr);
  ASSERT_EQ(version->count(), 2);
  EXPECT_EQ(version->itemText(0), QStringLiteral("0.21.0"));
  EXPECT_EQ(version->itemText(1), QStringLiteral("0.19.3"));
  EXPECT_EQ(version->currentIndex(), 0);
  version->setCurrentIndex(1);
  EXPECT_EQ(runs().run(1).backend().options().value("version"), 1.0);
  frames(3);
  EXPECT_GT(group().time(), 0.0) << "the run steps on the other release";
}

TEST_F(CompareMode, FourRunsOverlayEveryChartAndSideBySideGivesEachRunATile) {
  open(fooball::testing::gas(60));
  addRun(QStringLiteral("exact"));
  addRun(QStringLiteral("elastic"));
  // Through the run's own options form, as a user sets it.
  auto* substeps =
      runList()->optionsForm(2)->findChild<QSpinBox*>(QStringLiteral("option_substeps"));
  ASSERT_NE(substeps, nullptr);
  substeps->setValue(1);
  addRun(QStringLiteral("box2d"));
  ASSERT_EQ(runs().runCount(), 4);
  EXPECT_EQ(runs().label(2), QStringLiteral("elastic:substeps=1"));
  EXPECT_TRUE(runLegendText(*window->charts()).contains(QStringLiteral("elastic:substeps=1")))
      << runLegendText(*window->charts()).toStdString();
  EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("elastic:substeps=1")));
  frames(30);
  window->charts()->refresh();
  for (int run = 0; run < 4; ++run) {
    EXPECT_GT(storedSampleCount(*window->charts(), run), 5u) << "run " << run;
    EXPECT_GT(displayedPointCount(*window->charts(), ChartPanel::kEnergyChart, run), 1)
        << "run " << run;
  }
  window->actions().sideBySide()->trigger();
  std::vector<QRect> boxes;
  for (int run = 0; run < 4; ++run)
    boxes.push_back(view()->transformForRun(run).boxRect());
  for (int a = 0; a < 4; ++a) {
    // Each tile keeps the box's 16:9 aspect ratio, to a pixel.
    EXPECT_NEAR(boxes[a].width() * 9.0 / 16.0, boxes[a].height(), 1.5) << "tile " << a;
    for (int b = a + 1; b < 4; ++b)
      EXPECT_FALSE(boxes[a].intersects(boxes[b])) << "tiles " << a << " and " << b;
  }
}

TEST_F(CompareMode, AddingAndRemovingRunsKeepsTheChartHistory) {
  open(fooball::testing::gas(40));
  frames(30);
  const std::size_t before = storedSampleCount(*window->charts(), 0);
  ASSERT_GT(before, 5u);
  addRun(QStringLiteral("exact"));
  addRun(QStringLiteral("box2d"));
  EXPECT_GE(storedSampleCount(*window->charts(), 0), before) << "starting compare keeps history";
  frames(30);
  const std::size_t boxSamples = storedSampleCount(*window->charts(), 2);
  ASSERT_GT(boxSamples, 5u);
  QTest::mouseClick(runList()->removeButton(1), Qt::LeftButton);  // exact goes
  ASSERT_EQ(runs().runCount(), 2);
  EXPECT_EQ(runs().label(1), QStringLiteral("box2d"));
  EXPECT_EQ(storedSampleCount(*window->charts(), 1), boxSamples) << "box2d's curves move up";
  QTest::mouseClick(runList()->removeButton(1), Qt::LeftButton);
  EXPECT_EQ(runs().runCount(), 1);
  EXPECT_GE(storedSampleCount(*window->charts(), 0), before + 10) << "leaving keeps history";
  frames(5);
}

TEST_F(CompareMode, ANinthRunIsRefusedWithAMessage) {
  open(stillBalls());
  for (int i = 1; i < int(RunGroup::kMaxRuns); ++i)
    QTest::mouseClick(runList()->addButton(), Qt::LeftButton);
  EXPECT_EQ(runs().runCount(), int(RunGroup::kMaxRuns));
  EXPECT_FALSE(runList()->addButton()->isEnabled());
  EXPECT_THROW(runs().addRun(RunSpec{"elastic", {}}), std::invalid_argument);
  frames(3);
  for (int run = 1; run < runs().runCount(); ++run)
    EXPECT_EQ(runs().run(run).steps(), runs().run(0).steps());
}

TEST_F(CompareMode, HidingTheBaselineDropsItsCurves) {
  open(fooball::testing::gas(40), "elastic", {"exact"});
  ASSERT_TRUE(group().hasBaseline());
  runList()->baselineBox()->click();
  EXPECT_FALSE(group().hasBaseline());
  EXPECT_FALSE(window->compareReadout()->text().contains(QStringLiteral("baseline")));
}

TEST_F(CompareMode, ElasticRunsShareTheCoresAndTheSidebarShowsEachShare) {
  // A threads option follows the runs: all cores for one run, a share each with more runs
  // (the baseline counts), so runs in lockstep do not oversubscribe the machine.
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const auto threadsOf = [&](int run) {
    const Backend& backend = runs().run(run).backend();
    return backend.options().value(backend.options().withRole(OptionRole::Threads)->name);
  };
  const auto shownThreads = [&](int run) {
    return runList()->optionsForm(run)->findChild<QSpinBox*>(QStringLiteral("option_threads"));
  };
  open(fooball::testing::gas(50), "elastic");
  const OptionSpec* threads = mainRun().backend().options().withRole(OptionRole::Threads);
  ASSERT_NE(threads, nullptr);
  const double single = threadsOf(0);
  EXPECT_EQ(single, std::min<double>(cores, threads->max));
  ASSERT_NE(shownThreads(0), nullptr);
  EXPECT_EQ(shownThreads(0)->value(), single);

  addRun(QStringLiteral("elastic"));
  ASSERT_EQ(runs().runCount(), 2);
  ASSERT_TRUE(group().hasBaseline());
  const double share = std::max(1, cores / 3);  // two runs and the baseline
  for (int run = 0; run < 2; ++run) {
    EXPECT_EQ(threadsOf(run), share) << "run " << run;
    ASSERT_NE(shownThreads(run), nullptr);
    EXPECT_EQ(shownThreads(run)->value(), share) << "run " << run;
  }
  frames(10);
  EXPECT_EQ(group().divergence(1).maxPositionDifference, 0.0) << "threads change no result";

  QTest::mouseClick(runList()->removeButton(1), Qt::LeftButton);
  runList()->baselineBox()->click();
  EXPECT_EQ(threadsOf(0), single) << "one run again: all cores back";
}

}  // namespace
}  // namespace fooball::gui::testing
