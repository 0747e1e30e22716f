#include "tools/benchmark_dialog.h"

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
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "capacity_chart_builder.h"
#include "registry.h"
#include "tools/tool_run_panel.h"
#include "widgets/checklist.h"
#include "widgets/dark_theme.h"
#include "widgets/view_text.h"

namespace fooball::gui {

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

  run_ = new ToolRunPanel(ToolRunPanel::OnCancel::ShowFinished);
  run_->startButton()->setToolTip(tr("Run the capacity search for the checked backends"));
  run_->statusLabel()->setToolTip(
      tr("The backend and ball count measured last, and the time elapsed"));
  connect(run_, &ToolRunPanel::startRequested, this, [this] { start(); });
  connect(run_, &ToolRunPanel::runStarted, this, [this] {
    updateButtons();
    emit runStarted();
  });
  connect(run_, &ToolRunPanel::runFinished, this, [this] {
    liveResults_.clear();
    showResults();
    updateButtons();
    emit runFinished();
  });

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addWidget(createSettings());
  layout->addWidget(run_);
  layout->addWidget(createResults(), 1);

  showResults();
  updateButtons();
  resize(760, 720);
}

BenchmarkDialog::~BenchmarkDialog() {
  // The worker posts to this dialog (showProbe): it must be joined while the dialog is whole,
  // not when the panel, a child, goes with the rest of it.
  run_->stopAndJoin();
}

bool BenchmarkDialog::running() const {
  return run_->running();
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
  // Every row on show (a row per backend): the splitter's first share showed two and a half.
  const auto fitRows = [this] {
    const int rows = std::max(table_->rowCount(), 1);
    table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                             rows * table_->verticalHeader()->defaultSectionSize() +
                             2 * table_->frameWidth());
  };
  connect(table_->model(), &QAbstractItemModel::rowsInserted, this, fitRows);
  connect(table_->model(), &QAbstractItemModel::rowsRemoved, this, fitRows);

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
    run_->showError(QString::fromStdString(problem.what()));
    return false;
  }
  settings_ = settings;
  results_.clear();
  liveResults_.clear();
  const QString first = fromView(chosen.front().name);
  const auto job = [this, chosen = std::move(chosen), settings](
                       std::stop_token stop, const ToolRunPanel::Report& report) {
    const auto progress = [this, &report](const measure::CapacityProgress& at) {
      const measure::Probe& latest = at.search.latest;
      QMetaObject::invokeMethod(
          this,
          [this, backend = std::string(at.backend), latest] {
            showProbe(backend, latest.balls, latest.medianStepMs);
          },
          Qt::QueuedConnection);
      report(at.fraction, tr("%1 (%2 of %3): %L4 balls, median step %5 ms")
                              .arg(fromView(at.backend))
                              .arg(at.backendIndex + 1)
                              .arg(at.backendCount)
                              .arg(latest.balls)
                              .arg(latest.medianStepMs, 0, 'g', 3));
    };
    std::vector<measure::CapacityResult> results =
        measure::measureCapacity(chosen, settings, progress, stop);
    // A search cut short measured no capacity: its best count so far is no result.
    std::erase_if(results,
                  [](const measure::CapacityResult& result) { return result.outcome.cancelled; });
    return std::function<void()>([this, results = std::move(results)] { results_ = results; });
  };
  if (!run_->start(job, tr("Starting %1").arg(first))) return false;
  showResults();  // an empty table, and the chart waiting for its first count
  return true;
}

void BenchmarkDialog::showProbe(const std::string& backend, std::size_t balls,
                                double medianStepMs) {
  if (!running()) return;
  // The chart fills in while the search goes: every count measured so far, and the best one
  // within the budget as the capacity found so far.
  if (liveResults_.empty() || liveResults_.back().backend != backend) {
    liveResults_.push_back({backend, {}, {}});
  }
  measure::SearchOutcome& outcome = liveResults_.back().outcome;
  outcome.probes.push_back({balls, medianStepMs});
  if (medianStepMs <= settings_.budgetMs && balls > outcome.balls) {
    outcome.balls = balls;
    outcome.medianStepMs = medianStepMs;
  }
  showChart(liveResults_);
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
    cell(3, QString::fromStdString(measure::capacityNote(result)));
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

void BenchmarkDialog::updateButtons() {
  const bool busy = running();
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
    run_->showError(tr("%1: cannot write the CSV file").arg(path));
    return false;
  }
  return true;
}

bool BenchmarkDialog::savePng(const QString& path) {
  if (!chartView_->grab().save(path, "PNG")) {
    run_->showError(tr("%1: cannot write the PNG image").arg(path));
    return false;
  }
  return true;
}

void BenchmarkDialog::closeEvent(QCloseEvent* event) {
  run_->stopAndJoin();
  QDialog::closeEvent(event);
}

void BenchmarkDialog::reject() {
  run_->stopAndJoin();
  QDialog::reject();
}

}  // namespace fooball::gui
