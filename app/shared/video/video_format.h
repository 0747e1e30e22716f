#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fooball::video {

/// What a recording is written as, chosen by the file's extension.
enum class VideoFormat {
  Mp4,   ///< .mp4: H.264 (libx264), yuv420p: plays everywhere, the smallest for its quality
  WebM,  ///< .webm: VP9 (libvpx-vp9), or VP8 (libvpx) where VP9 is missing
  Gif,   ///< .gif: animated, 256 colours, for places that take only images
};

/// What to record: the picture's size and the frame rate.
struct VideoSettings {
  VideoFormat format = VideoFormat::Mp4;
  int width = 1280;          ///< px
  int height = 720;          ///< px
  int framesPerSecond = 60;  ///< recorded frames per second of video
};

/// The format of `path` by its extension, any case (".mp4", ".webm", ".gif"); nullopt for any
/// other.
std::optional<VideoFormat> videoFormatOf(std::string_view path);
/// "mp4", "webm", "gif".
std::string_view extensionOf(VideoFormat format);
/// "MP4 (H.264)", "WebM (VP9)", "animated GIF": for menus and messages.
std::string_view formatTitle(VideoFormat format);
/// The message for a path of no known format, naming its extension.
std::string unknownExtensionMessage(std::string_view path);

/// The frame rates a format plays back as recorded, fastest first. A GIF's frame delay is in
/// hundredths of a second and browsers play a delay below 2 of them at 10 frames/s, so a GIF
/// takes 50, 25, 20 or 10; MP4 and WebM take 60, 50, 30, 25 and 24.
std::vector<int> frameRatesFor(VideoFormat format);

/// Empty when `settings` can be recorded; otherwise one line saying what is wrong: a size out
/// of 16…16384 px, an odd width or height for MP4 or WebM (their 4:2:0 colour halves each side),
/// a frame rate the format does not play (frameRatesFor).
std::string checkVideoSettings(const VideoSettings& settings);

}  // namespace fooball::video
