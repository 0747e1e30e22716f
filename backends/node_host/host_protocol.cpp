#include "host_protocol.h"

namespace fooball::node_host {

void FrameWriter::begin(FrameKind kind) {
  bytes_.clear();
  u32Pair(0, static_cast<std::uint32_t>(kind));
}

void FrameWriter::append(const void* data, std::size_t size) {
  const std::size_t at = bytes_.size();
  bytes_.resize(at + size);
  if (size > 0) std::memcpy(bytes_.data() + at, data, size);
}

void FrameWriter::u32(std::uint32_t value) {
  append(&value, sizeof value);
}

void FrameWriter::f64(double value) {
  append(&value, sizeof value);
}

void FrameWriter::string(std::string_view text) {
  u32(static_cast<std::uint32_t>(text.size()));
  append(text.data(), text.size());
  bytes_.resize((bytes_.size() + 7) & ~std::size_t{7});
}

void FrameWriter::world(const WorldSettings& world) {
  f64(world.gravity.x);
  f64(world.gravity.y);
  f64(world.airResistance);
  const std::uint32_t flags = (world.walls.left ? 1u : 0u) | (world.walls.right ? 2u : 0u) |
                              (world.walls.bottom ? 4u : 0u) | (world.walls.top ? 8u : 0u) |
                              (world.ballCollisions ? 16u : 0u);
  u32Pair(flags, 0);
}

void FrameWriter::ball(const BallDef& ball) {
  const double values[] = {ball.position.x, ball.position.y, ball.velocity.x,
                           ball.velocity.y, ball.radius,     ball.mass};
  f64s(values);
}

void FrameWriter::end() {
  const auto payload = static_cast<std::uint32_t>(bytes_.size() - kHeaderBytes);
  std::memcpy(bytes_.data(), &payload, sizeof payload);
}

bool FrameReader::take(void* out, std::size_t size) {
  if (!ok_ || payload_.size() - offset_ < size) {
    ok_ = false;
    return false;
  }
  if (size > 0) std::memcpy(out, payload_.data() + offset_, size);
  offset_ += size;
  return true;
}

std::uint32_t FrameReader::u32() {
  std::uint32_t value = 0;
  take(&value, sizeof value);
  return value;
}

double FrameReader::f64() {
  double value = 0.0;
  take(&value, sizeof value);
  return value;
}

std::string_view FrameReader::string() {
  const std::uint32_t size = u32();
  if (!ok_ || payload_.size() - offset_ < size) {
    ok_ = false;
    return {};
  }
  const std::string_view text(reinterpret_cast<const char*>(payload_.data() + offset_), size);
  offset_ = std::min(payload_.size(), (offset_ + size + 7) & ~std::size_t{7});
  return text;
}

}  // namespace fooball::node_host
