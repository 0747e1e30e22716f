#include "readouts/status_panel.h"

#include <QLabel>
#include <QStatusBar>
#include <QTimer>

#include "fooball/cut_short_notice.h"
#include "fooball/limit_check.h"
#include "registry.h"
#include "run/frame_rate.h"
#include "run/run_controller.h"

namespace fooball::gui {

namespace {

/// s a step may run in the background before the status bar says how to give it up.
constexpr double kSlowStepNoticeSeconds = 1.0;
constexpr int kRefreshMs = 250;
constexpr int kNoticeMs = 8000;

}  // namespace

StatusPanel::StatusPanel(QStatusBar& bar, const RunController& runs, const FrameRate& frameRate)
    : QObject(&bar), bar_(bar), runs_(runs), frameRate_(frameRate) {
  cursor_ = addField(tr("Where the cursor is in the box, in metres (origin bottom-left)"));
  runsField_ = addField(tr("The run spec of each run (backend and options)"));
  balls_ = addField(tr("Balls in the scene"));
  time_ = addField(tr("Simulated time since the scene started"));
  steps_ = addField(tr("Physics steps per second of wall time (per run)"));
  frames_ = addField(tr("Frames drawn per second"));
  stepCost_ = addField(tr("Wall-clock milliseconds one physics step costs, per run"));
  cutShort_ = addField(QString());
  cutShort_->setObjectName(QStringLiteral("cutShortNotice"));
  cutShort_->setStyleSheet(QStringLiteral("color: #ffb347; font-weight: bold"));
  cutShort_->hide();
  limits_ = addField(QString());
  limits_->setObjectName(QStringLiteral("limitNotice"));
  limits_->setStyleSheet(cutShort_->styleSheet());
  limits_->hide();
  timer_ = new QTimer(this);
  timer_->setInterval(kRefreshMs);
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
  cursor_->setText(tr("x = %1 m, y = %2 m").arg(x, 0, 'f', 2).arg(y, 0, 'f', 2));
}

void StatusPanel::update() {
  QStringList costs;
  for (int i = 0; i < runs_.runCount(); ++i)
    costs << QString::number(runs_.stepTiming(i).millisecondsPerStep, 'f', 2);
  const double stepSeconds = runs_.stepSeconds();
  if (stepSeconds >= kSlowStepNoticeSeconds) {
    bar_.showMessage(tr("One physics step has taken %1 s so far. Pause (Space) gives it up.")
                         .arg(stepSeconds, 0, 'f', 1),
                     kNoticeMs);
  }
  showCutShortSteps();
  showCrossedLimits();
  runsField_->setText(runs_.labels().join(tr(" vs ")));
  balls_->setText(tr("%L1 balls").arg(runs_.group().ballCount()));
  time_->setText(tr("t = %1 s").arg(runs_.group().time(), 0, 'f', 2));
  steps_->setText(tr("%1 steps/s").arg(frameRate_.stepsPerSecond(), 0, 'f', 0));
  frames_->setText(tr("%1 frames/s").arg(frameRate_.framesPerSecond(), 0, 'f', 0));
  stepCost_->setText(runs_.stepping() ? tr("step: %1 s so far").arg(stepSeconds, 0, 'f', 1)
                                      : tr("%1 ms/step").arg(costs.join(QStringLiteral(" | "))));
}

void StatusPanel::showCutShortSteps() {
  QStringList runsCut;
  QStringList notices;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const std::string notice = cutShortNotice(runs_.group().run(std::size_t(i)).counters());
    if (notice.empty()) continue;
    runsCut << labels[i];
    notices << labels[i] + QStringLiteral(": ") + QString::fromStdString(notice);
  }
  cutShort_->setVisible(!notices.isEmpty());
  cutShort_->setText(tr("⚠ steps cut short: %1").arg(runsCut.join(QStringLiteral(", "))));
  cutShort_->setToolTip(notices.join(QLatin1Char('\n')));
}

void StatusPanel::showCrossedLimits() {
  if (runs_.stepping()) return;  // the backends are out: the last notice stands
  QStringList runsBeyond;
  QStringList explanations;
  const QStringList labels = runs_.labels();
  for (int i = 0; i < runs_.runCount(); ++i) {
    const std::size_t index = std::size_t(i);
    const MethodLimits& limits = backendInfo(runs_.group().spec(index).backend).limits;
    const std::vector<CrossedLimit> crossed = crossedLimits(runs_.group().run(index), limits);
    if (crossed.empty()) continue;
    QStringList names;
    for (const CrossedLimit& limit : crossed) {
      names << QString::fromStdString(limitName(limit.limit));
      explanations << labels[i] + QStringLiteral(": ") +
                          QString::fromStdString(limitExplanation(limit));
    }
    runsBeyond << (runs_.comparing() ? labels[i] + QStringLiteral(" (%1)").arg(names.join(", "))
                                     : names.join(QStringLiteral(", ")));
  }
  limits_->setVisible(!runsBeyond.isEmpty());
  limits_->setText(tr("⚠ beyond method limits: %1").arg(runsBeyond.join(QStringLiteral("; "))));
  limits_->setToolTip(explanations.join(QStringLiteral("\n\n")));
}

}  // namespace fooball::gui
