#include "recording_session.h"

#include "frames/frame_loop.h"
#include "run/run_controller.h"

namespace fooball::gui {

namespace {

video::VideoSettings videoSettings(const RecordingSettings& settings) {
  const std::string path = settings.path.toStdString();
  const auto format = video::videoFormatOf(path);
  if (!format) throw video::VideoError(video::unknownExtensionMessage(path));
  return {*format, settings.size.width(), settings.size.height(), settings.framesPerSecond};
}

}  // namespace

RecordingSession::RecordingSession(const RecordingTarget& target, const RecordingSettings& settings)
    : target_(target),
      settings_(settings),
      source_(target, settings.area, settings.size),
      encoder_(std::make_unique<video::VideoEncoder>(settings.path.toStdString(),
                                                     videoSettings(settings))) {
  clock_.start();
}

RecordingSession::~RecordingSession() {
  stop();
}

void RecordingSession::startLive() {
  live_ = true;
  target_.frames.setFixedFrameRate(settings_.framesPerSecond, [this] {
    // Paused, no simulated time passes: nothing to record.
    if (!target_.runs.paused()) takeFrame();
  });
}

bool RecordingSession::recordNextFrame() {
  if (stopped_) return false;
  target_.frames.advanceExactly(1.0 / settings_.framesPerSecond);
  return takeFrame();
}

bool RecordingSession::takeFrame() {
  if (stopped_) return false;
  const QImage& picture = source_.grab();
  try {
    encoder_->addFrame({picture.constBits(), picture.width(), picture.height(),
                        std::ptrdiff_t(picture.bytesPerLine())});
  } catch (const video::VideoError& error) {
    stop();  // the file keeps what was written, finished as far as the disk allows
    emit failed(QString::fromStdString(error.what()));
    return false;
  }
  emit frameRecorded();
  return true;
}

QString RecordingSession::stop() {
  if (stopped_) return {};
  stopped_ = true;
  if (live_) target_.frames.setFixedFrameRate(0.0);
  try {
    encoder_->finish();
  } catch (const video::VideoError& error) {
    return QString::fromStdString(error.what());
  }
  return {};
}

}  // namespace fooball::gui
