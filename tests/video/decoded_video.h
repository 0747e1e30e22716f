#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace fooball::testing {

/// A video file read back with FFmpeg's decoders: what its container says and what decoding
/// every frame gives.
struct DecodedVideo {
  std::string decoder;           ///< "h264", "vp9", "gif", …
  int width = 0;                 ///< px
  int height = 0;                ///< px
  int frameCount = 0;            ///< frames decoded
  double durationSeconds = 0.0;  ///< the container's duration
  double framesPerSecond = 0.0;  ///< the stream's average frame rate
  /// RGB24, rows packed (3·width bytes), of the frames asked for, in frame order.
  std::vector<std::vector<std::uint8_t>> frames;
  std::vector<int> frameIndices;  ///< which frame each of `frames` is
};

/// Decodes every frame of `path`, keeping the pixels of those in `keep`. Throws
/// std::runtime_error when the file does not open or decode.
DecodedVideo decodeVideo(const std::string& path, const std::set<int>& keep = {});

/// Mean |a − b| over every channel of every pixel, 0…255; both RGB24 of the same size.
double meanAbsoluteDifference(const std::vector<std::uint8_t>& a,
                              const std::vector<std::uint8_t>& b);

}  // namespace fooball::testing
