#pragma once

#include <QDialog>
#include <QElapsedTimer>
#include <QString>
#include <span>
#include <stop_token>
#include <thread>
#include <vector>

#include "capacity.h"

class QChartView;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTimer;

namespace fooball::gui {

/// Tools → Benchmark: the capacity search of `fooball-cli capacity` (fooball::measure) for the
/// chosen backends, on a worker thread so the window stays live, with progress, Cancel, a
/// table and the capacity chart of the CLI, saved as CSV (the CLI's columns) or PNG.
class BenchmarkDialog : public QDialog {
  Q_OBJECT

 public:
  explicit BenchmarkDialog(QWidget* parent = nullptr);
  /// Stops a run and waits for its thread: the search checks for a stop every step.
  ~BenchmarkDialog() override;

  /// From start() until the run's end is shown (runFinished), cancelled or not.
  bool running() const { return running_; }
  const std::vector<measure::CapacityResult>& results() const { return results_; }

  QListWidget* backendList() const { return backends_; }
  QLineEdit* budgetEdit() const { return budget_; }
  QLineEdit* optionsEdit() const { return options_; }
  QPushButton* startButton() const { return start_; }
  QPushButton* cancelButton() const { return cancel_; }
  QProgressBar* progressBar() const { return progress_; }
  QLabel* statusLabel() const { return status_; }
  QLabel* errorLabel() const { return error_; }
  QTableWidget* resultsTable() const { return table_; }
  QChartView* chartView() const { return chartView_; }

  /// Checks the settings and starts the search; on bad settings shows one error and starts
  /// nothing. Returns whether a run started.
  bool start();
  /// Asks the run to stop; it ends within one step and reports what it finished.
  void cancel();
  /// `capacity --csv`: backend,balls,median_step_ms. False (and an error shown) on failure.
  bool saveCsv(const QString& path);
  bool savePng(const QString& path);

 signals:
  /// A search starts or has ended (finished, cancelled or failed): the app pauses its own
  /// simulation in between, since both would share the CPU.
  void runStarted();
  void runFinished();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void reject() override;

 private:
  QWidget* createSettings();
  QWidget* createResults();
  measure::CapacitySettings settingsFromFields(std::vector<BackendInfo>& chosen) const;
  void showProgress(const QString& backend, std::size_t index, std::size_t count, std::size_t balls,
                    double medianStepMs, double fraction);
  void finishRun(std::vector<measure::CapacityResult> results, const QString& failure);
  void showResults();
  void showChart(std::span<const measure::CapacityResult> results);
  void showError(const QString& message);
  void updateButtons();
  /// Cancels a run and waits for its thread (the dialog is closing).
  void stopAndJoin();

  QListWidget* backends_;
  QLineEdit* budget_;
  QLineEdit* options_;
  QPushButton* start_;
  QPushButton* cancel_;
  QPushButton* saveCsv_;
  QPushButton* savePng_;
  QProgressBar* progress_;
  QLabel* status_;
  QLabel* error_;
  QTableWidget* table_;
  QChartView* chartView_;
  QTimer* elapsedTimer_;

  QElapsedTimer clock_;
  QString progressText_;                ///< the latest progress, without the elapsed time
  measure::CapacitySettings settings_;  ///< of the run shown or running
  std::vector<measure::CapacityResult> results_;
  /// While a run goes: what it measured so far, one entry per backend begun.
  std::vector<measure::CapacityResult> liveResults_;
  bool running_ = false;
  std::jthread worker_;  ///< last: destroyed (stopped and joined) before the widgets
};

}  // namespace fooball::gui
