#pragma once

#include <QDialog>
#include <QString>
#include <span>
#include <vector>

#include "capacity.h"

class QChartView;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace fooball::gui {

class ToolRunPanel;

/// Tools → Benchmark: the capacity search of `fooball-cli capacity` (fooball::measure) for the
/// chosen backends, on a ToolRunPanel's worker so the window stays live, with progress, Cancel,
/// a table and the capacity chart of the CLI, saved as CSV (the CLI's columns) or PNG. The
/// chart fills in as each ball count is measured; a cancelled run shows the backends it
/// finished.
class BenchmarkDialog : public QDialog {
  Q_OBJECT

 public:
  explicit BenchmarkDialog(QWidget* parent = nullptr);
  /// Stops a run and waits for its thread (the search checks for a stop every step) before
  /// anything the run's posted events would reach is gone.
  ~BenchmarkDialog() override;

  /// From start() until the run's end is shown (runFinished), cancelled or not.
  bool running() const;
  const std::vector<measure::CapacityResult>& results() const { return results_; }

  QListWidget* backendList() const { return backends_; }
  QLineEdit* budgetEdit() const { return budget_; }
  QLineEdit* optionsEdit() const { return options_; }
  ToolRunPanel* runPanel() const { return run_; }
  QTableWidget* resultsTable() const { return table_; }
  QChartView* chartView() const { return chartView_; }

  /// Checks the settings and starts the search; on bad settings shows one error and starts
  /// nothing. Returns whether a run started.
  bool start();
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
  /// A ball count measured (posted by the run's worker): the chart fills in.
  void showProbe(const std::string& backend, std::size_t balls, double medianStepMs);
  void showResults();
  void showChart(std::span<const measure::CapacityResult> results);
  void updateButtons();

  QListWidget* backends_;
  QLineEdit* budget_;
  QLineEdit* options_;
  ToolRunPanel* run_;
  QPushButton* saveCsv_;
  QPushButton* savePng_;
  QTableWidget* table_;
  QChartView* chartView_;

  measure::CapacitySettings settings_;  ///< of the run shown or running
  std::vector<measure::CapacityResult> results_;
  /// While a run goes: what it measured so far, one entry per backend begun.
  std::vector<measure::CapacityResult> liveResults_;
};

}  // namespace fooball::gui
