#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

#include "fooball/scene.h"

namespace fooball::node_host {

/// The binary protocol between a NodeHost and backends/js/host.js, which documents the frames.
/// Both sides are little-endian (x86-64 and AArch64 Linux; Node's typed arrays are native-endian,
/// and host.js reads with little-endian DataViews); every f64 sits at a multiple of 8.
inline constexpr std::uint32_t kProtocolVersion = 1;

enum class FrameKind : std::uint32_t {
  Hello = 1,
  Options = 2,
  Load = 3,
  World = 4,
  SetBall = 5,
  Step = 6,
  Ready = 100,
  State = 101,
  Error = 199,
};

inline constexpr std::size_t kHeaderBytes = 8;  ///< u32 payload bytes, u32 kind
/// Replies larger than this are garbage: 2 × the state of the 10 million balls no scene reaches.
inline constexpr std::uint32_t kMaxReplyBytes = 1u << 30;

/// Builds one request frame in a buffer that keeps its capacity from frame to frame.
class FrameWriter {
 public:
  void begin(FrameKind kind);
  void u32(std::uint32_t value);
  void u32Pair(std::uint32_t first, std::uint32_t second) {
    u32(first);
    u32(second);
  }
  void f64(double value);
  void f64s(std::span<const double> values) { raw(std::as_bytes(values)); }
  void raw(std::span<const std::byte> bytes) { append(bytes.data(), bytes.size()); }
  void string(std::string_view text);  ///< u32 bytes + UTF-8, padded to 8
  void world(const WorldSettings& world);
  void ball(const BallDef& ball);
  /// Writes the payload's size into the header; the frame is bytes().
  void end();
  std::span<const std::byte> bytes() const { return bytes_; }

 private:
  void append(const void* data, std::size_t size);
  std::vector<std::byte> bytes_;
};

/// The counters of a STATE reply, cumulative since the last LOAD.
struct HostCounters {
  double ballCollisions = 0.0;
  double wallCollisions = 0.0;
  double wallImpulse = 0.0;  ///< N·s
  double dragLoss = 0.0;     ///< J
  double engineSteps = 0.0;
  double ballsBroughtBack = 0.0;  ///< into the box by the adapter, past a wall that is on
  double stepSeconds = 0.0;       ///< s, wall-clock time inside the adapter's step (the engine's)
};
inline constexpr std::size_t kStateHeadBytes = 8 + 7 * 8;  ///< ball count, padding, counters

/// Reads fields in order from a received payload; any read past its end marks it garbage.
class FrameReader {
 public:
  explicit FrameReader(std::span<const std::byte> payload) : payload_(payload) {}
  std::uint32_t u32();
  double f64();
  std::string_view string();
  bool ok() const { return ok_; }
  std::size_t offset() const { return offset_; }

 private:
  bool take(void* out, std::size_t size);
  std::span<const std::byte> payload_;
  std::size_t offset_ = 0;
  bool ok_ = true;
};

}  // namespace fooball::node_host
