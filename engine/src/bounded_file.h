#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace fooball {

/// The whole contents of the file at `path`, refusing more than `maxBytes`: a regular file by
/// its size before reading a byte, anything else (a pipe) as soon as it delivers more. Throws
/// SceneError without the file name: "cannot open: No such file or directory", "cannot open: Is
/// a directory", "file is 600 MiB, larger than the 512 MiB limit", "cannot read: …".
std::string readBoundedFile(const std::filesystem::path& path, std::uintmax_t maxBytes);

}  // namespace fooball
