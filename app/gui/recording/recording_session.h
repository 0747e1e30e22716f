#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QSize>
#include <QString>
#include <memory>

#include "recording_frame_source.h"
#include "video_encoder.h"

namespace fooball::gui {

/// What File → Record… and `fooball --record` record.
struct RecordingSettings {
  QString path;  ///< .mp4, .webm or .gif (video::videoFormatOf)
  RecordArea area = RecordArea::Box;
  QSize size{1280, 720};     ///< px, the video's
  int framesPerSecond = 60;  ///< video::frameRatesFor(format)
};

/// One recording of the window: a frame source and an encoder, with the frames taken at fixed
/// simulated time — each frame 1/fps s of video holds exactly speed/fps s of simulation
/// (FrameLoop::advanceExactly), so the video neither stutters nor races when the machine is
/// busy; the window then runs slower than real time instead. Pausing the simulation pauses the
/// recording. The file is finished whichever way the recording ends — stop(), an error, the
/// session destroyed with its window — so it always plays (video::VideoEncoder).
class RecordingSession : public QObject {
  Q_OBJECT

 public:
  /// Opens the file. Throws video::VideoError (unknown type, bad settings, unwritable path).
  RecordingSession(const RecordingTarget& target, const RecordingSettings& settings);
  /// Stops (stop()), silently.
  ~RecordingSession() override;

  /// The app: from now on the window's frame loop ticks at the recording's frame rate, and
  /// each tick is one recorded frame.
  void startLive();
  /// One frame now, whatever drives the window (`fooball --record`): 1/fps s of video.
  /// Returns false, after failed(), when the frame could not be written.
  bool recordNextFrame();
  /// Ends the recording: the frame loop back to real time, the file finished. Returns an error
  /// message if the file could not be finished, empty otherwise; further calls do nothing.
  QString stop();

  bool recording() const { return !stopped_; }
  const RecordingSettings& settings() const { return settings_; }
  int frames() const { return encoder_->framesAdded(); }
  /// s of video recorded.
  double seconds() const { return encoder_->seconds(); }
  /// The file's size so far.
  qint64 bytes() const { return qint64(encoder_->bytesWritten()); }
  /// s of real time since the start.
  double elapsedSeconds() const { return double(clock_.elapsed()) / 1000.0; }
  QString codecName() const { return QString::fromStdString(encoder_->codecName()); }
  /// The last recorded picture, before encoding (lossless).
  const QImage& lastFrame() const { return source_.image(); }

 signals:
  /// A frame was written.
  void frameRecorded();
  /// The recording stopped on an error; the file keeps the frames before it. `message` is one
  /// line naming the file and the problem.
  void failed(const QString& message);

 private:
  /// Grabs the picture and encodes it; on an error, stops and emits failed().
  bool takeFrame();

  RecordingTarget target_;
  RecordingSettings settings_;
  RecordingFrameSource source_;
  std::unique_ptr<video::VideoEncoder> encoder_;
  QElapsedTimer clock_;
  bool live_ = false;
  bool stopped_ = false;
};

}  // namespace fooball::gui
