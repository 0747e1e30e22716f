#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "rgb_frame.h"
#include "video_format.h"

namespace fooball::video {

/// A recording that cannot go on; what() is one line naming the file and the problem, e.g.
/// "out.mp4: could not write: No space left on device (the disk is full)".
class VideoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes RGB frames to a video file with FFmpeg's libraries, at a constant frame rate: frame k
/// is shown from k/fps to (k+1)/fps s. The file is finished (the encoder drained, the container's
/// index and trailer written, the file closed) by finish(), or by the destructor when finish()
/// was not called — after an error, a stop or an exception alike — so a recording cut short is
/// still a playable file of the frames written so far. Not thread-safe; one thread at a time.
class VideoEncoder {
 public:
  /// Opens `path` (created or truncated) for `settings`. Throws VideoError: settings that
  /// checkVideoSettings refuses, no encoder for the format in this FFmpeg, a file that cannot
  /// be created.
  VideoEncoder(const std::string& path, const VideoSettings& settings);
  /// Finishes the file if finish() has not; errors then are swallowed (nothing to tell them to).
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  /// Encodes the next frame; its size must be the settings'. Throws VideoError (a write that
  /// failed: disk full, file gone; a frame of the wrong size); the file is still finished later.
  void addFrame(const RgbFrame& frame);
  /// Drains the encoder, writes the trailer and closes the file. Throws VideoError when the
  /// file could not be completed. Further calls do nothing.
  void finish();

  const VideoSettings& settings() const { return settings_; }
  const std::string& path() const { return path_; }
  /// The encoder FFmpeg chose: "libx264", "libvpx-vp9", "libvpx", "gif".
  std::string codecName() const;
  int framesAdded() const { return framesAdded_; }
  /// s of video so far: framesAdded / fps.
  double seconds() const { return double(framesAdded_) / settings_.framesPerSecond; }
  /// Bytes written to the file so far (what the encoder holds back for later frames excluded).
  std::int64_t bytesWritten() const;
  bool finished() const { return finished_; }

 private:
  struct Ffmpeg;  ///< the FFmpeg contexts, freed in order
  /// Sends `frame` (nullptr: the end) and writes every packet the encoder has ready.
  void encode(bool flush);
  [[noreturn]] void fail(const std::string& what, int error) const;

  std::string path_;
  VideoSettings settings_;
  std::unique_ptr<Ffmpeg> ffmpeg_;
  int framesAdded_ = 0;
  bool finished_ = false;
  std::int64_t finalBytes_ = 0;
};

}  // namespace fooball::video
