#include "benchmark_dialog.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QCloseEvent>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "capacity_chart_builder.h"
#include "checklist.h"
#include "dark_theme.h"
#include "registry.h"
#include "view_text.h"

namespace fooball::gui {

namespace {

constexpr int kProgressSteps = 1000;  ///< the progress bar's maximum: 0.1 % resolution
constexpr int kElapsedRefreshMs = 200;

QString noteOf(const measure::SearchOutcome& outcome) {
  if (outcome.reachedMaxBalls) return QObject::tr("the scene format's limit: capacity is higher");
  if (outcome.timedOut) return QObject::tr("time limit: best count so far");
  return {};
}

}  // namespace

BenchmarkDialog::BenchmarkDialog(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("benchmarkDialog"));
  setWindowTitle(tr("Benchmark: capacity"));

  auto* intro = new QLabel(
      tr("The most balls each backend steps within the budget: the standard gas, run "
         "untimed for %1 s of simulated time so it has thermalised, then the median of %2 "
         "steps per ball count, the same search as <tt>fooball-cli capacity</tt>. "
         "<b>The simulation in the main window is paused while the benchmark runs</b> (both "
         "would share the CPU) and continues afterwards.")
          .arg(measure::CapacitySettings{}.warmUpSeconds)
          .arg(measure::CapacitySettings{}.timedSteps));
  intro->setWordWrap(true);

  start_ = new QPushButton(tr("&Start"));
  start_->setToolTip(tr("Run the capacity search for the checked backends"));
  cancel_ = new QPushButton(tr("&Cancel run"));
  cancel_->setToolTip(tr("Stop the search; it ends within one physics step"));
  progress_ = new QProgressBar;
  progress_->setRange(0, kProgressSteps);
  progress_->setValue(0);
  progress_->setToolTip(tr("An estimate of the whole run's progress"));
  status_ = new QLabel(tr("Not started"));
  status_->setToolTip(tr("The backend and ball count measured last, and the time elapsed"));
  error_ = new QLabel;
  error_->setObjectName(QStringLiteral("benchmarkError"));
  error_->setStyleSheet(QStringLiteral("color: #ff7b7b;"));
  error_->setWordWrap(true);
  error_->hide();
  connect(start_, &QPushButton::clicked, this, &BenchmarkDialog::start);
  connect(cancel_, &QPushButton::clicked, this, &BenchmarkDialog::cancel);

  auto* runRow = new QHBoxLayout;
  runRow->addWidget(start_);
  runRow->addWidget(cancel_);
  runRow->addWidget(progress_, 1);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addWidget(createSettings());
  layout->addLayout(runRow);
  layout->addWidget(status_);
  layout->addWidget(error_);
  layout->addWidget(createResults(), 1);

  elapsedTimer_ = new QTimer(this);
  elapsedTimer_->setInterval(kElapsedRefreshMs);
  connect(elapsedTimer_, &QTimer::timeout, this, [this] {
    status_->setText(tr("%1 — %2 s elapsed")
                         .arg(progressText_)
                         .arg(double(clock_.elapsed()) / 1000.0, 0, 'f', 1));
  });

  showResults();
  updateButtons();
  resize(760, 720);
}

BenchmarkDialog::~BenchmarkDialog() {
  worker_.request_stop();
  // ~jthread joins; the progress and result events the worker posted die with this object.
}

QWidget* BenchmarkDialog::createSettings() {
  auto* settings = new QWidget;
  auto* form = new QFormLayout(settings);
  form->setContentsMargins(0, 0, 0, 0);

  backends_ = newBackendChecklist(tr("The backends to measure, one after another"));
  form->addRow(tr("&Backends:"), backends_);

  budget_ = new QLineEdit(QString::number(measure::CapacitySettings{}.budgetMs, 'g', 4));
  budget_->setToolTip(
      tr("Milliseconds one step may take, e.g. 16.67 (one frame at 60 Hz); must be > 0"));
  form->addRow(tr("B&udget (ms per step):"), budget_);

  options_ = new QLineEdit;
  options_->setPlaceholderText(tr("e.g. substeps=1"));
  options_->setToolTip(
      tr("Backend options as KEY=VALUE, separated by spaces; each applies to the backends that "
         "have it (see fooball-cli list). Empty: every backend's defaults"));
  form->addRow(tr("&Options:"), options_);
  return settings;
}

QWidget* BenchmarkDialog::createResults() {
  table_ = new QTableWidget(0, 4);
  table_->setHorizontalHeaderLabels(
      {tr("backend"), tr("balls"), tr("median step (ms)"), tr("note")});
  // Each column as wide as its header or its widest cell, whichever is wider, so the header
  // reads in full before the first result too; the note takes the rest.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setToolTip(
      tr("Each backend's capacity: the most balls whose median step fits the "
         "budget, and that step's cost"));

  chartView_ = new QChartView;
  chartView_->setRenderHint(QPainter::Antialiasing);
  chartView_->setMinimumHeight(320);
  chartView_->setToolTip(
      tr("Median step against ball count for every count measured; the dashed line is the "
         "budget, the large dots the capacities"));

  saveCsv_ = new QPushButton(tr("Save C&SV…"));
  saveCsv_->setToolTip(tr("Save the table as backend,balls,median_step_ms (as capacity --csv)"));
  savePng_ = new QPushButton(tr("Save &PNG…"));
  savePng_->setToolTip(tr("Save the chart as a PNG image"));
  connect(saveCsv_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save capacity CSV"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (!path.isEmpty()) saveCsv(path);
  });
  connect(savePng_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save capacity chart"), QString(),
                                                      tr("PNG images (*.png)"));
    if (!path.isEmpty()) savePng(path);
  });
  auto* close = new QPushButton(tr("C&lose"));
  close->setToolTip(tr("Close the dialog; a run still going is cancelled"));
  connect(close, &QPushButton::clicked, this, &QDialog::close);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(saveCsv_);
  buttons->addWidget(savePng_);
  buttons->addStretch(1);
  buttons->addWidget(close);

  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(table_);
  splitter->addWidget(chartView_);
  // A row per backend needs little room; the chart's log axes and titles need height.
  splitter->setSizes({120, 420});

  auto* results = new QWidget;
  auto* column = new QVBoxLayout(results);
  column->setContentsMargins(0, 0, 0, 0);
  column->addWidget(splitter, 1);
  column->addLayout(buttons);
  return results;
}

measure::CapacitySettings BenchmarkDialog::settingsFromFields(
    std::vector<BackendInfo>& chosen) const {
  measure::CapacitySettings settings;
  bool isNumber = false;
  settings.budgetMs = budget_->text().trimmed().toDouble(&isNumber);
  // Not a number at all reads as NaN, which checkCapacitySettings names as a bad budget.
  if (!isNumber) settings.budgetMs = std::numeric_limits<double>::quiet_NaN();
  for (const QString& option : options_->text().split(QLatin1Char(' '), Qt::SkipEmptyParts))
    settings.options.push_back(option.toStdString());
  chosen = checkedBackends(*backends_);
  return settings;
}

bool BenchmarkDialog::start() {
  if (running()) return false;
  std::vector<BackendInfo> chosen;
  measure::CapacitySettings settings = settingsFromFields(chosen);
  try {
    if (chosen.empty()) throw std::invalid_argument("backends: check at least one");
    measure::checkCapacitySettings(chosen, settings);
  } catch (const std::invalid_argument& problem) {
    showError(QString::fromStdString(problem.what()));
    return false;
  }
  error_->hide();
  settings_ = settings;
  results_.clear();
  liveResults_.clear();
  running_ = true;
  showResults();
  progress_->setValue(0);
  progressText_ = tr("Starting %1").arg(fromView(chosen.front().name));
  status_->setText(progressText_);
  clock_.start();
  elapsedTimer_->start();
  emit runStarted();

  worker_ = std::jthread([this, chosen = std::move(chosen), settings](std::stop_token stop) {
    const auto progress = [this](const measure::CapacityProgress& at) {
      QMetaObject::invokeMethod(
          this,
          [this, backend = fromView(at.backend), index = at.backendIndex, count = at.backendCount,
           balls = at.search.latest.balls, ms = at.search.latest.medianStepMs,
           fraction = at.fraction] { showProgress(backend, index, count, balls, ms, fraction); },
          Qt::QueuedConnection);
    };
    std::vector<measure::CapacityResult> results;
    QString failure;
    try {
      results = measure::measureCapacity(chosen, settings, progress, stop);
    } catch (const std::exception& problem) {
      failure = QString::fromStdString(problem.what());
    }
    QMetaObject::invokeMethod(
        this,
        [this, results = std::move(results), failure]() mutable {
          finishRun(std::move(results), failure);
        },
        Qt::QueuedConnection);
  });
  updateButtons();
  return true;
}

void BenchmarkDialog::cancel() {
  if (!running()) return;
  worker_.request_stop();
  progressText_ = tr("Cancelling…");
  status_->setText(progressText_);
}

void BenchmarkDialog::showProgress(const QString& backend, std::size_t index, std::size_t count,
                                   std::size_t balls, double medianStepMs, double fraction) {
  if (!running() || worker_.get_stop_token().stop_requested()) return;
  // The chart fills in while the search goes: every count measured so far, and the best one
  // within the budget as the capacity found so far.
  const std::string name = backend.toStdString();
  if (liveResults_.empty() || liveResults_.back().backend != name) {
    liveResults_.push_back({name, {}, {}});
  }
  measure::SearchOutcome& outcome = liveResults_.back().outcome;
  outcome.probes.push_back({balls, medianStepMs});
  if (medianStepMs <= settings_.budgetMs && balls > outcome.balls) {
    outcome.balls = balls;
    outcome.medianStepMs = medianStepMs;
  }
  showChart(liveResults_);
  progress_->setValue(static_cast<int>(std::lround(fraction * kProgressSteps)));
  progressText_ = tr("%1 (%2 of %3): %L4 balls, median step %5 ms")
                      .arg(backend)
                      .arg(index + 1)
                      .arg(count)
                      .arg(balls)
                      .arg(medianStepMs, 0, 'g', 3);
  status_->setText(progressText_);
}

void BenchmarkDialog::finishRun(std::vector<measure::CapacityResult> results,
                                const QString& failure) {
  const bool cancelled = worker_.get_stop_token().stop_requested();
  if (worker_.joinable()) worker_.join();
  running_ = false;
  elapsedTimer_->stop();
  // A search cut short measured no capacity: its best count so far is no result.
  std::erase_if(results,
                [](const measure::CapacityResult& result) { return result.outcome.cancelled; });
  results_ = std::move(results);
  liveResults_.clear();
  const double seconds = double(clock_.elapsed()) / 1000.0;
  if (!failure.isEmpty()) {
    showError(failure);
    status_->setText(tr("Failed after %1 s").arg(seconds, 0, 'f', 1));
  } else if (cancelled) {
    status_->setText(
        tr("Cancelled after %1 s; only the backends finished are shown").arg(seconds, 0, 'f', 1));
  } else {
    progress_->setValue(kProgressSteps);
    status_->setText(tr("Done in %1 s").arg(seconds, 0, 'f', 1));
  }
  showResults();
  updateButtons();
  emit runFinished();
}

void BenchmarkDialog::showResults() {
  table_->setRowCount(static_cast<int>(results_.size()));
  int row = 0;
  for (const measure::CapacityResult& result : results_) {
    const auto cell = [this, row](int column, const QString& text) {
      auto* item = new QTableWidgetItem(text);
      if (column == 1 || column == 2) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(row, column, item);
    };
    cell(0, QString::fromStdString(result.backend));
    cell(1, QString::number(result.outcome.balls));
    cell(2, QString::number(result.outcome.medianStepMs, 'g', 4));
    cell(3, noteOf(result.outcome));
    ++row;
  }
  showChart(results_);
}

void BenchmarkDialog::showChart(std::span<const measure::CapacityResult> results) {
  QChart* previous = chartView_->chart();
  QChart* chart = plots::makeCapacityChart(results, settings_);
  chart->setTitle(plots::capacityChartTitle(settings_));
  bool measured = false;
  for (const measure::CapacityResult& result : results)
    measured = measured || !result.outcome.probes.empty();
  if (!measured) {
    // Axes with nothing on them read as a broken chart: say what will appear instead.
    for (QAbstractAxis* axis : chart->axes())
      axis->hide();
    chart->setTitle(running() ? tr("Measuring the first ball count…")
                              : tr("Press Start: each backend's step time appears here as each "
                                   "ball count is measured"));
  }
  styleChartDark(*chart);
  chartView_->setChart(chart);  // the view owns the new chart and gives the old one back
  delete previous;
}

void BenchmarkDialog::showError(const QString& message) {
  error_->setText(message);
  error_->show();
}

void BenchmarkDialog::updateButtons() {
  const bool busy = running();
  start_->setEnabled(!busy);
  cancel_->setEnabled(busy);
  backends_->setEnabled(!busy);
  budget_->setEnabled(!busy);
  options_->setEnabled(!busy);
  saveCsv_->setEnabled(!busy && !results_.empty());
  savePng_->setEnabled(!busy && !results_.empty());
}

bool BenchmarkDialog::saveCsv(const QString& path) {
  std::ofstream csv(QFile::encodeName(path).toStdString());
  measure::writeCapacityCsv(csv, results_);
  csv.close();
  if (!csv) {
    showError(tr("%1: cannot write the CSV file").arg(path));
    return false;
  }
  return true;
}

bool BenchmarkDialog::savePng(const QString& path) {
  if (!chartView_->grab().save(path, "PNG")) {
    showError(tr("%1: cannot write the PNG image").arg(path));
    return false;
  }
  return true;
}

void BenchmarkDialog::stopAndJoin() {
  if (!worker_.joinable()) return;
  worker_.request_stop();
  worker_.join();
  // finishRun still comes (the worker posted it) and shows what was finished.
}

void BenchmarkDialog::closeEvent(QCloseEvent* event) {
  stopAndJoin();
  QDialog::closeEvent(event);
}

void BenchmarkDialog::reject() {
  stopAndJoin();
  QDialog::reject();
}

}  // namespace fooball::gui
