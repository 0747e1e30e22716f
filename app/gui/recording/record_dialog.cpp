#include "record_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include "frames/frame_loop.h"
#include "video_format.h"

namespace fooball::gui {

namespace {

/// Video sizes offered besides the area's own: the common 16:9 ones.
const QSize kSizes[] = {{1920, 1080}, {1280, 720}, {854, 480}, {640, 360}};

/// An even size no larger than `size`: H.264 and VP9 halve the colour resolution each way.
QSize evenSize(QSize size) {
  return {std::max(16, size.width() & ~1), std::max(16, size.height() & ~1)};
}

QString sizeText(QSize size) {
  return QStringLiteral("%1×%2").arg(size.width()).arg(size.height());
}

}  // namespace

RecordDialog::RecordDialog(const RecordingTarget& target, QWidget& parent)
    : QDialog(&parent), target_(target) {
  setObjectName(QStringLiteral("recordDialog"));
  setWindowTitle(tr("Record"));

  path_ = new QLineEdit(QDir::home().filePath(QStringLiteral("fooball.mp4")));
  path_->setToolTip(tr("The type follows the extension: .mp4 (H.264), .webm (VP9) or .gif"));
  auto* browse = new QPushButton(tr("Browse…"));
  auto* pathRow = new QHBoxLayout;
  pathRow->addWidget(path_, 1);
  pathRow->addWidget(browse);

  area_ = new QComboBox;
  area_->addItem(tr("The box"), int(RecordArea::Box));
  area_->addItem(tr("The box and the charts"), int(RecordArea::BoxAndCharts));
  area_->setToolTip(
      tr("The box with its legend row and run labels, or the charts beside it too (as in the "
         "window)"));

  size_ = new QComboBox;
  size_->addItem(QString(), QSize());  // as shown: its text follows the window (showEvent)
  for (const QSize size : kSizes)
    size_->addItem(sizeText(size), size);
  size_->setToolTip(
      tr("The video's size. At the size shown the video is the screen's picture pixel for pixel; "
         "at another the picture is drawn again at that scale, centred on black where the shapes "
         "differ"));

  rate_ = new QComboBox;
  rate_->setToolTip(
      tr("Frames per second of video. A GIF's frame delay is in hundredths of a "
         "second, so it takes 50, 25, 20 or 10"));

  note_ = new QLabel;
  note_->setWordWrap(true);
  progress_ = new QLabel(tr("Not recording"));
  progress_->setObjectName(QStringLiteral("recordProgress"));
  startStop_ = new QPushButton(tr("Start"));
  startStop_->setDefault(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  buttons->addButton(startStop_, QDialogButtonBox::ActionRole);

  auto* form = new QFormLayout;
  auto* pathLabel = new QLabel(tr("&File:"));  // a row of a layout gets no buddy by itself
  pathLabel->setBuddy(path_);
  form->addRow(pathLabel, pathRow);
  form->addRow(tr("&Record:"), area_);
  form->addRow(tr("&Size:"), size_);
  form->addRow(tr("Frame &rate:"), rate_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(note_);
  layout->addWidget(progress_);
  layout->addWidget(buttons);
  setMinimumWidth(520);  // room for a path

  connect(browse, &QPushButton::clicked, this, &RecordDialog::browse);
  connect(path_, &QLineEdit::textChanged, this, &RecordDialog::offerFrameRates);
  connect(area_, &QComboBox::currentIndexChanged, this, &RecordDialog::updateNote);
  connect(startStop_, &QPushButton::clicked, this, [this] {
    if (session_) {
      stop();
    } else {
      start();
    }
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::hide);
  offerFrameRates();
  updateNote();
}

RecordDialog::~RecordDialog() = default;  // the session finishes its file

void RecordDialog::showEvent(QShowEvent* event) {
  QDialog::showEvent(event);
  updateNote();  // the size shown and the speed may have changed while it was closed
}

void RecordDialog::browse() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Record to"), path_->text(),
      tr("MP4 video (*.mp4);;WebM video (*.webm);;Animated GIF (*.gif)"));
  if (!path.isEmpty()) path_->setText(path);
}

void RecordDialog::offerFrameRates() {
  const auto format = video::videoFormatOf(path_->text().toStdString());
  const int chosen = rate_->currentData().isValid() ? rate_->currentData().toInt() : 60;
  rate_->clear();
  for (const int rate : video::frameRatesFor(format.value_or(video::VideoFormat::Mp4)))
    rate_->addItem(tr("%1 frames/s").arg(rate), rate);
  const int index = rate_->findData(chosen);
  // A GIF cannot take 60: its nearest, 50.
  rate_->setCurrentIndex(index >= 0 ? index : 0);
}

void RecordDialog::updateNote() {
  const QSize shown =
      evenSize(RecordingFrameSource::shownSize(target_, RecordArea(area_->currentData().toInt())));
  size_->setItemText(0, tr("As shown (%1)").arg(sizeText(shown)));
  note_->setText(
      tr("A recorded second is a simulated second times the speed slider (now %1×). Every frame "
         "holds the same simulated time, so a busy machine records slower than real time, never "
         "a jerky video. Pausing pauses the recording.")
          .arg(QLocale().toString(target_.frames.timeScale(), 'g', 3)));
}

RecordingSettings RecordDialog::settings() const {
  RecordingSettings settings;
  settings.path = path_->text().trimmed();
  settings.area = RecordArea(area_->currentData().toInt());
  const QSize chosen = size_->currentData().toSize();
  settings.size =
      chosen.isValid() ? chosen : evenSize(RecordingFrameSource::shownSize(target_, settings.area));
  settings.framesPerSecond = rate_->currentData().toInt();
  return settings;
}

bool RecordDialog::start() {
  if (session_) return false;
  updateNote();
  const RecordingSettings chosen = settings();
  try {
    session_ = std::make_unique<RecordingSession>(target_, chosen);
  } catch (const video::VideoError& error) {
    emit errorToReport(tr("Could not record"), QString::fromStdString(error.what()));
    return false;
  }
  connect(session_.get(), &RecordingSession::frameRecorded, this, &RecordDialog::showProgress);
  connect(session_.get(), &RecordingSession::failed, this, [this](const QString& message) {
    showStopped(tr("Stopped: %1").arg(message));
    emit errorToReport(tr("The recording stopped"), message);
  });
  for (QWidget* field : {static_cast<QWidget*>(path_), static_cast<QWidget*>(area_),
                         static_cast<QWidget*>(size_), static_cast<QWidget*>(rate_)})
    field->setEnabled(false);
  startStop_->setText(tr("Stop"));
  session_->startLive();
  showProgress();
  emit statusToShow(tr("Recording to %1").arg(chosen.path));
  return true;
}

void RecordDialog::showProgress() {
  if (!session_) return;
  const QLocale locale;
  progress_->setText(tr("Recording: %1 s of video (%2 frames) in %3 s, %4")
                         .arg(session_->seconds(), 0, 'f', 1)
                         .arg(session_->frames())
                         .arg(session_->elapsedSeconds(), 0, 'f', 1)
                         .arg(locale.formattedDataSize(session_->bytes())));
}

void RecordDialog::stop() {
  if (!session_) return;
  const QString error = session_->stop();
  if (!error.isEmpty()) {
    showStopped(tr("Stopped: %1").arg(error));
    emit errorToReport(tr("The recording could not be finished"), error);
    return;
  }
  const QString message = tr("Saved %1: %2 s of video (%3 frames), %4")
                              .arg(QFileInfo(session_->settings().path).fileName())
                              .arg(session_->seconds(), 0, 'f', 1)
                              .arg(session_->frames())
                              .arg(QLocale().formattedDataSize(session_->bytes()));
  emit statusToShow(message);
  showStopped(message);
}

void RecordDialog::showStopped(const QString& message) {
  // Later: the session may be what emitted the signal that brought us here.
  if (session_) session_.release()->deleteLater();
  for (QWidget* field : {static_cast<QWidget*>(path_), static_cast<QWidget*>(area_),
                         static_cast<QWidget*>(size_), static_cast<QWidget*>(rate_)})
    field->setEnabled(true);
  startStop_->setText(tr("Start"));
  progress_->setText(message);
}

}  // namespace fooball::gui
