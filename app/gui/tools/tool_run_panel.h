#pragma once

#include <QElapsedTimer>
#include <QString>
#include <QWidget>
#include <functional>
#include <stop_token>
#include <thread>

class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;

namespace fooball::gui {

/// What the Tools dialogs share: Start and Cancel, a progress bar, a status line with the time
/// elapsed and an error line, and the worker thread a measurement runs on so that the window
/// stays live. The dialog checks its settings when Start is pressed (startRequested) and hands
/// start() the job.
class ToolRunPanel : public QWidget {
  Q_OBJECT

 public:
  /// Called by the job on its worker thread, as often as it likes: the fraction of the whole run
  /// done, in [0, 1], and what it is doing.
  using Report = std::function<void(double fraction, const QString& doing)>;
  /// Runs on the worker; returns what shows its results, which the panel calls on the GUI thread
  /// when the job ended by itself, or also when it was cancelled under OnCancel::ShowFinished.
  /// The job throws std::exception to fail with one line of error.
  using Job = std::function<std::function<void()>(std::stop_token stop, const Report& report)>;

  /// What a cancelled run shows. A trade-off or a failure map cancelled midway would be half a
  /// result: nothing shows. A benchmark's results are per backend, each whole: the backends it
  /// finished show.
  enum class OnCancel { ShowNothing, ShowFinished };

  explicit ToolRunPanel(OnCancel onCancel = OnCancel::ShowNothing, QWidget* parent = nullptr);
  /// Stops a run and waits for its thread.
  ~ToolRunPanel() override;

  /// From start() until the run's end is shown (runFinished), cancelled or not.
  bool running() const { return running_; }

  QPushButton* startButton() const { return start_; }
  QPushButton* cancelButton() const { return cancel_; }
  QProgressBar* progressBar() const { return progress_; }
  QLabel* statusLabel() const { return status_; }
  QLabel* errorLabel() const { return error_; }

  /// Starts `job` on the worker, `starting` on the status line. False if a run is going.
  bool start(Job job, const QString& starting);
  /// Asks the run to stop; the job ends at its next check and its results are dropped.
  void cancel();
  /// Cancels a run and waits for its thread (the dialog is closing).
  void stopAndJoin();
  void showError(const QString& message);

 signals:
  /// Start was pressed: the dialog checks its settings and calls start().
  void startRequested();
  void runStarted();
  /// The run has ended (finished, cancelled or failed) and its results, if any, are shown.
  void runFinished();

 private:
  void showProgress(double fraction, const QString& doing);
  void finishRun(const std::function<void()>& showResults, const QString& failure);

  QPushButton* start_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* status_;
  QLabel* error_;
  QTimer* elapsedTimer_;
  QElapsedTimer clock_;
  QString doing_;  ///< the latest progress, without the elapsed time
  bool running_ = false;
  OnCancel onCancel_;
  std::jthread worker_;  ///< last: destroyed (stopped and joined) before the widgets
};

}  // namespace fooball::gui
