#include "readouts/status_panel.h"

#include <QLabel>
#include <QStatusBar>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "fooball/cut_short_notice.h"
#include "fooball/limit_check.h"
#include "fooball/metrics.h"
#include "readouts/readout_cells.h"
#include "registry.h"
#include "run/frame_rate.h"
#include "run/run_controller.h"
#include "widgets/view_text.h"

namespace fooball::gui {

namespace {

/// s a step may run in the background before the status bar says how to give it up.
constexpr double kSlowStepNoticeSeconds = 1.0;
constexpr int kNoticeMs = 8000;
/// px: the widest the notices shown may grow together, so that with eight runs at 1000 px the
/// fields and the timeline all fit; each tooltip has its notice whole.
constexpr int kNoticeWidth = 300;
/// The property that keeps a notice's whole text while its label shows it cut short.
constexpr char kWholeText[] = "wholeText";

/// `paragraphs` as rich text, so the tooltip wraps at a readable width instead of
/// running one line across the screen.
QString wrappedToolTip(const QStringList& paragraphs) {
  QString html;
  for (const QString& paragraph : paragraphs)
    html += QStringLiteral("<p>%1</p>").arg(paragraph.toHtmlEscaped());
  return html;
}

/// A notice: `heading` (with "%1" for `items`, joined by `separator`), and `explanations` in its
/// tooltip; hidden when there are no items. shareNoticeWidth() cuts it to its share.
void showNotice(QLabel& notice, const QString& heading, const QStringList& items,
                const QString& separator, const QStringList& explanations) {
  notice.setVisible(!items.isEmpty());
  notice.setProperty(kWholeText, heading.arg(items.join(separator)));
  notice.setToolTip(wrappedToolTip(explanations));
}

/// The notices shown share kNoticeWidth: each is cut short with "…" past an equal share.
void shareNoticeWidth(std::initializer_list<QLabel*> notices) {
  const auto shown = std::count_if(notices.begin(), notices.end(),
                                   [](const QLabel* notice) { return !notice->isHidden(); });
  if (shown == 0) return;
  const int share = kNoticeWidth / int(shown);
  for (QLabel* notice : notices) {
    notice->setText(notice->fontMetrics().elidedText(notice->property(kWholeText).toString(),
                                                     Qt::ElideRight, share));
  }
}

}  // namespace

StatusPanel::StatusPanel(QStatusBar& bar, const RunController& runs, const FrameRate& frameRate)
    : QObject(&bar), bar_(bar), runs_(runs), frameRate_(frameRate) {
  cursor_ = addField(tr("Where the cursor is in the box, in metres (origin bottom-left)"));
  // The runs are named in the window's title and the Counters, not here: with eight runs
  // their specs would leave the timeline no room.
  ballsAndTime_ = addField(tr("Balls in the scene, and the simulated time since it started"));
  rates_ =
      addField(tr("Physics steps per second of wall time (per run), and frames drawn per "
                  "second"));
  stepCost_ = addField(QString());
  cutShort_ = addField(QString());
  cutShort_->setObjectName(QStringLiteral("cutShortNotice"));
  cutShort_->setStyleSheet(QStringLiteral("color: #ffb347; font-weight: bold"));
  cutShort_->hide();
  energy_ = addField(QString());
  energy_->setObjectName(QStringLiteral("energyNotice"));
  energy_->setStyleSheet(cutShort_->styleSheet());
  energy_->hide();
  limits_ = addField(QString());
  limits_->setObjectName(QStringLiteral("limitNotice"));
  limits_->setStyleSheet(cutShort_->styleSheet());
  limits_->hide();
  timer_ = new QTimer(this);
  timer_->setInterval(kReadoutRefreshMs);
  connect(timer_, &QTimer::timeout, this, &StatusPanel::update);
}

QLabel* StatusPanel::addField(const QString& toolTip) {
  auto* label = new QLabel;
  label->setToolTip(toolTip);
  bar_.addPermanentWidget(label);
  return label;
}

void StatusPanel::start() {
  timer_->start();
}

void StatusPanel::showCursor(double x, double y) {
  cursor_->setText(tr("(%1, %2) m").arg(x, 0, 'f', 2).arg(y, 0, 'f', 2));
}

void StatusPanel::update() {
  QStringList costs;
  double slowest = 0.0;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const double cost = runs_.stepTiming(i).millisecondsPerStep;
    slowest = std::max(slowest, cost);
    costs << tr("%1: %2 ms").arg(labels[i]).arg(cost, 0, 'f', 2);
  }
  const double stepSeconds = runs_.stepSeconds();
  if (stepSeconds >= kSlowStepNoticeSeconds) {
    bar_.showMessage(tr("One physics step has taken %1 s so far. Pause (Space) gives it up.")
                         .arg(stepSeconds, 0, 'f', 1),
                     kNoticeMs);
  }
  showCutShortSteps();
  showEnergyErrors();
  showCrossedLimits();
  shareNoticeWidth({cutShort_, energy_, limits_});
  ballsAndTime_->setText(tr("%L1 balls, t = %2 s")
                             .arg(runs_.group().ballCount())
                             .arg(runs_.group().time(), 0, 'f', 2));
  rates_->setText(tr("%1 steps/s, %2 fps")
                      .arg(frameRate_.stepsPerSecond(), 0, 'f', 0)
                      .arg(frameRate_.framesPerSecond(), 0, 'f', 0));
  // The slowest run's: it sets the pace of the group; each run's cost is in the tooltip.
  stepCost_->setText(runs_.stepping() ? tr("step: %1 s so far").arg(stepSeconds, 0, 'f', 1)
                                      : tr("%1 ms/step").arg(slowest, 0, 'f', 2));
  stepCost_->setToolTip(wrappedToolTip(
      QStringList{tr("Wall-clock milliseconds one physics step costs, the slowest run's shown; "
                     "per run:")} +
      costs));
}

QString StatusPanel::runName(int index) const {
  // In compare mode the runs' specs would not fit side by side: their numbers, as the counters
  // and the legend show them, and the specs in the tooltip.
  return runs_.comparing() ? tr("run %1").arg(index) : runs_.labels()[index];
}

void StatusPanel::showCutShortSteps() {
  QStringList runsCut;
  QStringList notices;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const std::string notice = cutShortNotice(runs_.group().run(std::size_t(i)).counters());
    if (notice.empty()) continue;
    runsCut << runName(i);
    notices << labels[i] + QStringLiteral(": ") + QString::fromStdString(notice);
  }
  showNotice(*cutShort_, tr("⚠ steps cut short: %1"), runsCut, QStringLiteral(", "), notices);
}

void StatusPanel::showEnergyErrors() {
  if (runs_.stepping()) return;  // the backends are out: the last notice stands
  QStringList shown;
  QStringList explanations;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const Simulation& run = runs_.group().run(std::size_t(i));
    const double error = relativeEnergyError(run.metrics(GeometryChecks::Skip));
    // Past kEnergyErrorLimit the limit notice says it (NaN: no energy to be relative to).
    if (!(std::abs(error) >= kNoticeableEnergyError && std::abs(error) <= kEnergyErrorLimit))
      continue;
    const QString percent = QStringLiteral("%1%2 %")
                                .arg(error > 0.0 ? QStringLiteral("+") : QString())
                                .arg(100.0 * error, 0, 'g', 2);
    shown << (runs_.comparing() ? tr("run %1 %2").arg(i).arg(percent) : percent);
    QString explanation =
        tr("%1 has %2 %3 of the energy it started with: the method's own error (the energy "
           "budget's residual, Help → Reading the charts). FooBall points it out from %4 %, a step "
           "the energy chart shows plainly.")
            .arg(labels[i], error > 0.0 ? tr("gained") : tr("lost"),
                 QString::number(100.0 * std::abs(error), 'g', 2),
                 QString::number(100.0 * kNoticeableEnergyError));
    QStringList remedies;
    const OptionSet& options = run.backend().options();
    for (const OptionRole role : {OptionRole::Substeps, OptionRole::Iterations}) {
      if (const OptionSpec* option = options.withRole(role))
        remedies << tr("raise %1 (%2)").arg(fromView(option->name), fromView(option->description));
    }
    if (!remedies.isEmpty()) {
      explanation += tr(" To lower it, in the run's options under Runs in the sidebar: %1.")
                         .arg(remedies.join(tr("; or ")));
    }
    explanations << explanation;
  }
  showNotice(*energy_, tr("⚠ energy error: %1"), shown, QStringLiteral(", "), explanations);
}

void StatusPanel::showCrossedLimits() {
  if (runs_.stepping()) return;  // the backends are out: the last notice stands
  // Each limit once, with the runs beyond it: four limits at most, however many runs.
  QStringList limitNames;
  std::vector<QStringList> runsBeyond;
  QStringList explanations;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const std::size_t index = std::size_t(i);
    const MethodLimits& limits = backendInfo(runs_.group().spec(index).backend).limits;
    for (const CrossedLimit& limit : crossedLimits(runs_.group().run(index), limits)) {
      const QString name = QString::fromStdString(limitName(limit.limit));
      if (!limitNames.contains(name)) {
        limitNames << name;
        runsBeyond.emplace_back();
      }
      runsBeyond[std::size_t(limitNames.indexOf(name))] << QString::number(i);
      explanations << labels[i] + QStringLiteral(": ") +
                          QString::fromStdString(limitExplanation(limit));
    }
  }
  // Limits the same runs are beyond share one group, the runs first (a cut text keeps them):
  // "runs 0, 2: tunnelling, resting pile".
  std::vector<std::pair<QStringList, QStringList>> groups;  // limit names, run indices
  for (std::size_t k = 0; k < runsBeyond.size(); ++k) {
    const auto same = std::ranges::find_if(
        groups, [&](const auto& group) { return group.second == runsBeyond[k]; });
    if (same != groups.end()) {
      same->first << limitNames[qsizetype(k)];
    } else {
      groups.push_back({{limitNames[qsizetype(k)]}, runsBeyond[k]});
    }
  }
  QStringList parts;
  for (const auto& [names, indices] : groups) {
    const QString limitsText = names.join(QStringLiteral(", "));
    parts << (!runs_.comparing()    ? limitsText
              : indices.size() == 1 ? tr("run %1: %2").arg(indices.front(), limitsText)
                                    : tr("runs %1: %2").arg(indices.join(", "), limitsText));
  }
  showNotice(*limits_, tr("⚠ method limits — %1"), parts, QStringLiteral("; "), explanations);
}

}  // namespace fooball::gui
