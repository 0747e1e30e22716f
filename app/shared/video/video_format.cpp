#include "video_format.h"

#include <algorithm>
#include <cctype>

namespace fooball::video {

namespace {

constexpr int kMinSide = 16;     // px: a smaller video is no picture
constexpr int kMaxSide = 16384;  // px: the largest --size, beyond any screen

std::string lowerExtension(std::string_view path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
  std::string extension(path.substr(dot + 1));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

}  // namespace

std::optional<VideoFormat> videoFormatOf(std::string_view path) {
  const std::string extension = lowerExtension(path);
  if (extension == "mp4") return VideoFormat::Mp4;
  if (extension == "webm") return VideoFormat::WebM;
  if (extension == "gif") return VideoFormat::Gif;
  return std::nullopt;
}

std::string_view extensionOf(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4:
      return "mp4";
    case VideoFormat::WebM:
      return "webm";
    case VideoFormat::Gif:
      return "gif";
  }
  return {};
}

std::string_view formatTitle(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4:
      return "MP4 (H.264)";
    case VideoFormat::WebM:
      return "WebM (VP9)";
    case VideoFormat::Gif:
      return "animated GIF";
  }
  return {};
}

std::string unknownExtensionMessage(std::string_view path) {
  const std::string extension = lowerExtension(path);
  return std::string(path) + ": unknown video type " +
         (extension.empty() ? std::string("(no extension)") : "'." + extension + "'") +
         " (use .mp4, .webm or .gif)";
}

std::vector<int> frameRatesFor(VideoFormat format) {
  if (format == VideoFormat::Gif) return {50, 25, 20, 10};
  return {60, 50, 30, 25, 24};
}

std::string checkVideoSettings(const VideoSettings& settings) {
  const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
  if (settings.width < kMinSide || settings.height < kMinSide || settings.width > kMaxSide ||
      settings.height > kMaxSide) {
    return "video size " + size + ": each side from " + std::to_string(kMinSide) + " to " +
           std::to_string(kMaxSide) + " px";
  }
  if (settings.format != VideoFormat::Gif &&
      (settings.width % 2 != 0 || settings.height % 2 != 0)) {
    return "video size " + size + ": " + std::string(formatTitle(settings.format)) +
           " needs an even width and height";
  }
  const std::vector<int> rates = frameRatesFor(settings.format);
  if (std::find(rates.begin(), rates.end(), settings.framesPerSecond) == rates.end()) {
    std::string list;
    for (const int rate : rates)
      list += (list.empty() ? "" : ", ") + std::to_string(rate);
    return std::to_string(settings.framesPerSecond) +
           " frames/s: " + std::string(formatTitle(settings.format)) + " plays " + list +
           (settings.format == VideoFormat::Gif ? " (its frame delay is in hundredths of a second)"
                                                : "");
  }
  return {};
}

}  // namespace fooball::video
