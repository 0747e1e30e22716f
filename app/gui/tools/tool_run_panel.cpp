#include "tools/tool_run_panel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <exception>

namespace fooball::gui {

namespace {

constexpr int kProgressSteps = 1000;  ///< the progress bar's maximum: 0.1 % resolution
constexpr int kElapsedRefreshMs = 200;

QString secondsText(const QElapsedTimer& clock) {
  return QString::number(double(clock.elapsed()) / 1000.0, 'f', 1);
}

}  // namespace

ToolRunPanel::ToolRunPanel(OnCancel onCancel, QWidget* parent)
    : QWidget(parent), onCancel_(onCancel) {
  start_ = new QPushButton(tr("&Start"));
  start_->setToolTip(tr("Run the measurement with the settings above"));
  cancel_ = new QPushButton(tr("&Cancel run"));
  cancel_->setToolTip(onCancel == OnCancel::ShowNothing
                          ? tr("Stop the run; it ends after the measurement under way and "
                               "shows nothing of it")
                          : tr("Stop the run; it ends after the measurement under way and "
                               "shows what it finished"));
  cancel_->setEnabled(false);
  progress_ = new QProgressBar;
  progress_->setRange(0, kProgressSteps);
  progress_->setValue(0);
  progress_->setToolTip(tr("The share of the run's measurements done"));
  status_ = new QLabel(tr("Not started"));
  status_->setToolTip(tr("What is being measured, and the time elapsed"));
  error_ = new QLabel;
  error_->setStyleSheet(QStringLiteral("color: #ff7b7b;"));
  error_->setWordWrap(true);
  error_->hide();
  connect(start_, &QPushButton::clicked, this, &ToolRunPanel::startRequested);
  connect(cancel_, &QPushButton::clicked, this, &ToolRunPanel::cancel);

  auto* runRow = new QHBoxLayout;
  runRow->addWidget(start_);
  runRow->addWidget(cancel_);
  runRow->addWidget(progress_, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(runRow);
  layout->addWidget(status_);
  layout->addWidget(error_);

  elapsedTimer_ = new QTimer(this);
  elapsedTimer_->setInterval(kElapsedRefreshMs);
  connect(elapsedTimer_, &QTimer::timeout, this,
          [this] { status_->setText(tr("%1 — %2 s elapsed").arg(doing_, secondsText(clock_))); });
}

ToolRunPanel::~ToolRunPanel() {
  worker_.request_stop();
  // ~jthread joins; the progress and result events the worker posted die with this object.
}

bool ToolRunPanel::start(Job job, const QString& starting) {
  if (running()) return false;
  error_->hide();
  running_ = true;
  progress_->setValue(0);
  doing_ = starting;
  status_->setText(doing_);
  clock_.start();
  elapsedTimer_->start();
  start_->setEnabled(false);
  cancel_->setEnabled(true);
  emit runStarted();

  worker_ = std::jthread([this, job = std::move(job)](std::stop_token stop) {
    const Report report = [this](double fraction, const QString& doing) {
      QMetaObject::invokeMethod(
          this, [this, fraction, doing] { showProgress(fraction, doing); }, Qt::QueuedConnection);
    };
    std::function<void()> showResults;
    QString failure;
    try {
      showResults = job(stop, report);
    } catch (const std::exception& problem) {
      failure = QString::fromStdString(problem.what());
    }
    QMetaObject::invokeMethod(
        this, [this, showResults, failure] { finishRun(showResults, failure); },
        Qt::QueuedConnection);
  });
  return true;
}

void ToolRunPanel::cancel() {
  if (!running()) return;
  worker_.request_stop();
  doing_ = tr("Cancelling…");
  status_->setText(doing_);
}

void ToolRunPanel::showProgress(double fraction, const QString& doing) {
  if (!running() || worker_.get_stop_token().stop_requested()) return;
  progress_->setValue(static_cast<int>(std::lround(fraction * kProgressSteps)));
  doing_ = doing;
  status_->setText(doing_);
}

void ToolRunPanel::finishRun(const std::function<void()>& showResults, const QString& failure) {
  const bool cancelled = worker_.get_stop_token().stop_requested();
  if (worker_.joinable()) worker_.join();
  running_ = false;
  elapsedTimer_->stop();
  if (!failure.isEmpty()) {
    showError(failure);
    status_->setText(tr("Failed after %1 s").arg(secondsText(clock_)));
  } else if (cancelled && onCancel_ == OnCancel::ShowNothing) {
    progress_->setValue(0);
    status_->setText(
        tr("Cancelled after %1 s; nothing of the run is shown").arg(secondsText(clock_)));
  } else if (cancelled) {
    status_->setText(
        tr("Cancelled after %1 s; only what it finished is shown").arg(secondsText(clock_)));
    if (showResults) showResults();
  } else {
    progress_->setValue(kProgressSteps);
    status_->setText(tr("Done in %1 s").arg(secondsText(clock_)));
    if (showResults) showResults();
  }
  start_->setEnabled(true);
  cancel_->setEnabled(false);
  emit runFinished();
}

void ToolRunPanel::stopAndJoin() {
  if (!worker_.joinable()) return;
  worker_.request_stop();
  worker_.join();
  // finishRun still comes (the worker posted it).
}

void ToolRunPanel::showError(const QString& message) {
  error_->setText(message);
  error_->show();
}

}  // namespace fooball::gui
