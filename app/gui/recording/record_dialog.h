#pragma once

#include <QDialog>
#include <QSize>
#include <memory>

#include "recording_session.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace fooball::gui {

/// File → Record…: where to, what (the box, or the box and the charts), the video's size and
/// frame rate, and Start/Stop with the video's length and the file's size while it records. Not
/// modal: the window stays live, and closing the dialog keeps recording (File → Record… shows
/// it again). The recording itself is a RecordingSession the dialog owns.
class RecordDialog : public QDialog {
  Q_OBJECT

 public:
  /// Records `target`; a dialog of `parent`.
  RecordDialog(const RecordingTarget& target, QWidget& parent);
  ~RecordDialog() override;

  /// Starts with the settings shown; on a bad setting or a file that cannot be written, reports
  /// one error (errorToReport) and starts nothing. Returns whether it started.
  bool start();
  /// Stops and finishes the file; says how it went.
  void stop();
  /// The recording going on, or nullptr.
  RecordingSession* session() const { return session_.get(); }
  /// The settings the fields show now ("as shown" resolved to the window's size of now).
  RecordingSettings settings() const;

  QLineEdit* pathField() const { return path_; }
  QComboBox* areaChoice() const { return area_; }
  QComboBox* sizeChoice() const { return size_; }
  QComboBox* rateChoice() const { return rate_; }
  QPushButton* startButton() const { return startStop_; }
  QLabel* progressLabel() const { return progress_; }

 signals:
  /// An error for the user (the window's error reporter).
  void errorToReport(const QString& title, const QString& message);
  /// A line for the status bar: the recording started, or where it was saved.
  void statusToShow(const QString& message);

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  void browse();
  /// The frame rates the file's type plays, keeping the one chosen where it can.
  void offerFrameRates();
  void showProgress();
  /// After a stop or an error: the fields editable again, the button back to Start.
  void showStopped(const QString& message);
  void updateNote();

  RecordingTarget target_;
  QLineEdit* path_;
  QComboBox* area_;
  QComboBox* size_;
  QComboBox* rate_;
  QLabel* note_;
  QLabel* progress_;
  QPushButton* startStop_;
  std::unique_ptr<RecordingSession> session_;
};

}  // namespace fooball::gui
