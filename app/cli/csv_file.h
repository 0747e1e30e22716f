#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace fooball::cli {

/// A CSV file a command writes: created (truncated) with its header line, then whole rows, and
/// checked on close, so that a full disk or a bad path is an error naming the flag and the path.
class CsvFile {
 public:
  /// Throws UsageError ("--csv 'out.csv': cannot open for writing: …") when `path` cannot be
  /// created, so a bad path fails before any simulation.
  CsvFile(const std::filesystem::path& path, std::string_view flag, std::string_view header);

  /// Appends `row`, which ends with its own '\n'.
  void write(std::string_view row);
  /// Flushes and closes; throws std::runtime_error when the data did not reach the file.
  void close();

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  std::filesystem::path path_;
  std::string flag_;
  std::unique_ptr<std::FILE, FileCloser> file_;
};

}  // namespace fooball::cli
