#include "bounded_file.h"

#include <cerrno>
#include <cmath>
#include <fstream>
#include <system_error>
#include <vector>

#include "fooball/scene_error.h"
#include "message_text.h"

namespace fooball {
namespace {

[[noreturn]] void failToOpen(std::errc reason) {
  throw SceneError("cannot open: " + std::make_error_code(reason).message());
}

/// A size for people: MiB, rounded up to a tenth so a file just over the limit does not read
/// as "512 MiB, larger than the 512 MiB limit".
std::string mebibytesText(std::uintmax_t bytes) {
  const double tenths = std::ceil(static_cast<double>(bytes) / static_cast<double>(1 << 20) * 10.0);
  return exactNumberText(tenths / 10.0) + " MiB";
}

[[noreturn]] void failTooLarge(std::uintmax_t bytes, std::uintmax_t maxBytes) {
  throw SceneError("file is " + mebibytesText(bytes) + ", larger than the " +
                   mebibytesText(maxBytes) + " limit");
}

}  // namespace

std::string readBoundedFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    failToOpen(std::errc::no_such_file_or_directory);
  }
  if (error) throw SceneError("cannot open: " + error.message());
  if (std::filesystem::is_directory(status)) failToOpen(std::errc::is_a_directory);
  std::string text;
  if (std::filesystem::is_regular_file(status)) {
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw SceneError("cannot open: " + error.message());
    if (size > maxBytes) failTooLarge(size, maxBytes);
    text.reserve(static_cast<std::size_t>(size));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError("cannot open: " + std::error_code(errno, std::generic_category()).message());
  constexpr std::size_t kChunkBytes = 1 << 20;
  std::vector<char> chunk(kChunkBytes);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > maxBytes) failTooLarge(text.size(), maxBytes);
  }
  if (in.bad())
    throw SceneError("cannot read: " + std::error_code(errno, std::generic_category()).message());
  return text;
}

}  // namespace fooball
