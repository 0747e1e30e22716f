#include "video_encoder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "decoded_video.h"

namespace fooball::video {
namespace {

using testing::decodeVideo;
using testing::meanAbsoluteDifference;

/// A picture like FooBall's: a black box, a grey frame line, a white and two coloured discs that
/// move a few pixels a frame, and a coloured bar whose length counts the frames.
std::vector<std::uint8_t> syntheticFrame(int width, int height, int index) {
  std::vector<std::uint8_t> rgb(std::size_t(3 * width * height), 0);
  const auto put = [&](int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* pixel = &rgb[std::size_t(3 * (y * width + x))];
    pixel[0] = r;
    pixel[1] = g;
    pixel[2] = b;
  };
  for (int x = 0; x < width; ++x) {
    put(x, 2, 128, 128, 128);
    put(x, height - 3, 128, 128, 128);
  }
  const struct {
    double x, y, vx, radius;
    std::uint8_t r, g, b;
  } discs[] = {{20, 30, 3, 9, 240, 240, 240},
               {90, 50, -2, 12, 224, 160, 48},
               {60, 20, 1.5, 6, 60, 140, 230}};
  for (const auto& disc : discs) {
    const double cx = std::fmod(disc.x + disc.vx * index + 10.0 * width, double(width));
    for (int y = int(disc.y - disc.radius); y <= int(disc.y + disc.radius); ++y) {
      for (int x = int(cx - disc.radius); x <= int(cx + disc.radius); ++x) {
        if (std::hypot(x - cx, y - disc.y) <= disc.radius) put(x, y, disc.r, disc.g, disc.b);
      }
    }
  }
  for (int x = 0; x < 2 * index && x < width; ++x) {
    for (int y = height - 12; y < height - 6; ++y)
      put(x, y, 200, 60, 60);
  }
  return rgb;
}

RgbFrame frameOf(const std::vector<std::uint8_t>& rgb, int width, int height) {
  return {rgb.data(), width, height, std::ptrdiff_t(3 * width)};
}

class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "fooball-video-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

struct FormatCase {
  VideoFormat format;
  int framesPerSecond;
  const char* decoder;
  /// Mean |Δ| a channel (0…255) a decoded frame may differ from what went in. H.264 and VP9
  /// keep flat colours but halve the colour resolution (4:2:0) and blur sharp edges: on these
  /// small frames, edges everywhere a disc or the bar is, that is ~1 of 255 (measured 0.4 to
  /// 1.2 for both, growing with the red bar); about twice that is allowed. A GIF keeps every colour
  /// of its first frame exactly, and shows a colour first seen later (the red bar) as the
  /// nearest of its palette's 4×4×4 cube, up to 42 of 255 a channel off on those pixels: 0.9 on
  /// the last frame.
  double tolerance;
};

class EncodeDecode : public ::testing::TestWithParam<FormatCase> {};

TEST_P(EncodeDecode, GivesBackEveryFrameAtItsSizeRateAndDuration) {
  const FormatCase& c = GetParam();
  constexpr int kWidth = 160;
  constexpr int kHeight = 90;
  constexpr int kFrames = 40;
  TemporaryFolder folder;
  const std::string path = folder.file("out." + std::string(extensionOf(c.format)));
  std::vector<std::vector<std::uint8_t>> sent;
  {
    VideoEncoder encoder(path, {c.format, kWidth, kHeight, c.framesPerSecond});
    for (int i = 0; i < kFrames; ++i) {
      sent.push_back(syntheticFrame(kWidth, kHeight, i));
      encoder.addFrame(frameOf(sent.back(), kWidth, kHeight));
    }
    EXPECT_EQ(encoder.framesAdded(), kFrames);
    EXPECT_DOUBLE_EQ(encoder.seconds(), double(kFrames) / c.framesPerSecond);
    encoder.finish();
    EXPECT_EQ(encoder.bytesWritten(), std::int64_t(std::filesystem::file_size(path)));
  }
  const auto decoded = decodeVideo(path, {0, kFrames / 2, kFrames - 1});
  EXPECT_EQ(decoded.decoder, c.decoder);
  EXPECT_EQ(decoded.width, kWidth);
  EXPECT_EQ(decoded.height, kHeight);
  EXPECT_EQ(decoded.frameCount, kFrames);
  EXPECT_NEAR(decoded.durationSeconds, double(kFrames) / c.framesPerSecond,
              0.5 / c.framesPerSecond);
  ASSERT_EQ(decoded.frames.size(), 3u);
  for (std::size_t k = 0; k < decoded.frames.size(); ++k) {
    const int index = decoded.frameIndices[k];
    const double difference = meanAbsoluteDifference(decoded.frames[k], sent[index]);
    EXPECT_LT(difference, c.tolerance) << "frame " << index;
    // And it is that frame, not a neighbour: five frames on, the discs have moved.
    const int other = index < kFrames / 2 ? index + 5 : index - 5;
    EXPECT_GT(meanAbsoluteDifference(decoded.frames[k], sent[other]), 2.0 * difference + 1.0)
        << "frame " << index << " against " << other;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, EncodeDecode,
                         ::testing::Values(FormatCase{VideoFormat::Mp4, 60, "h264", 2.2},
                                           FormatCase{VideoFormat::WebM, 30, "vp9", 2.2},
                                           FormatCase{VideoFormat::Gif, 25, "gif", 1.5}),
                         [](const auto& formatCase) {
                           return std::string(extensionOf(formatCase.param.format));
                         });

TEST(VideoEncoder, ARecordingCutShortIsStillPlayable) {
  // No finish(): the destructor writes the trailer, as after a stop, an error or a closed app.
  TemporaryFolder folder;
  for (const VideoFormat format : {VideoFormat::Mp4, VideoFormat::WebM, VideoFormat::Gif}) {
    const std::string path = folder.file("cut." + std::string(extensionOf(format)));
    {
      VideoEncoder encoder(path, {format, 64, 48, 25});
      for (int i = 0; i < 7; ++i) {
        const auto rgb = syntheticFrame(64, 48, i);
        encoder.addFrame(frameOf(rgb, 64, 48));
      }
    }
    const auto decoded = decodeVideo(path);
    EXPECT_EQ(decoded.frameCount, 7) << path;
  }
}

TEST(VideoEncoder, ExtensionsChooseTheFormatAndOthersAreNamed) {
  EXPECT_EQ(videoFormatOf("a/b.mp4"), VideoFormat::Mp4);
  EXPECT_EQ(videoFormatOf("B.WebM"), VideoFormat::WebM);
  EXPECT_EQ(videoFormatOf("c.gif"), VideoFormat::Gif);
  EXPECT_EQ(videoFormatOf("movie.avi"), std::nullopt);
  EXPECT_EQ(videoFormatOf("dir.mp4/movie"), std::nullopt);
  EXPECT_EQ(unknownExtensionMessage("movie.avi"),
            "movie.avi: unknown video type '.avi' (use .mp4, .webm or .gif)");
  EXPECT_EQ(unknownExtensionMessage("movie"),
            "movie: unknown video type (no extension) (use .mp4, .webm or .gif)");
}

TEST(VideoEncoder, SettingsItCannotPlayAreOneLineEach) {
  EXPECT_EQ(checkVideoSettings({VideoFormat::Mp4, 1280, 720, 60}), "");
  EXPECT_EQ(checkVideoSettings({VideoFormat::Gif, 641, 361, 25}), "");
  EXPECT_EQ(checkVideoSettings({VideoFormat::Mp4, 1281, 720, 60}),
            "video size 1281x720: MP4 (H.264) needs an even width and height");
  EXPECT_EQ(checkVideoSettings({VideoFormat::Gif, 640, 360, 60}),
            "60 frames/s: animated GIF plays 50, 25, 20, 10 (its frame delay is in hundredths of "
            "a second)");
  EXPECT_EQ(checkVideoSettings({VideoFormat::WebM, 8, 8, 30}),
            "video size 8x8: each side from 16 to 16384 px");
  TemporaryFolder folder;
  try {
    VideoEncoder encoder(folder.file("odd.mp4"), {VideoFormat::Mp4, 101, 100, 60});
    FAIL() << "an odd width was taken";
  } catch (const VideoError& error) {
    EXPECT_NE(std::string(error.what()).find("needs an even width"), std::string::npos);
  }
}

TEST(VideoEncoder, AnUnwritablePathSaysWhy) {
  try {
    VideoEncoder encoder("/nonexistent-folder/out.mp4", {VideoFormat::Mp4, 64, 48, 60});
    FAIL() << "no error";
  } catch (const VideoError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/nonexistent-folder/out.mp4: could not create the file: No such file or directory");
  }
}

TEST(VideoEncoder, AFullDiskSaysSo) {
  // /dev/full takes the file's creation and refuses every write with ENOSPC, as a full disk does.
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  std::string message;
  try {
    VideoEncoder encoder("/dev/full", {VideoFormat::Gif, 160, 90, 25});
    for (int i = 0; i < 30; ++i) {
      const auto rgb = syntheticFrame(160, 90, i);
      encoder.addFrame(frameOf(rgb, 160, 90));
    }
    encoder.finish();
  } catch (const VideoError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("/dev/full: "), std::string::npos) << message;
  EXPECT_NE(message.find("(the disk is full)"), std::string::npos) << message;
}

TEST(VideoEncoder, AFrameOfAnotherSizeIsRefused) {
  TemporaryFolder folder;
  VideoEncoder encoder(folder.file("size.webm"), {VideoFormat::WebM, 64, 48, 30});
  const auto rgb = syntheticFrame(32, 48, 0);
  EXPECT_THROW(encoder.addFrame(frameOf(rgb, 32, 48)), VideoError);
}

}  // namespace
}  // namespace fooball::video
