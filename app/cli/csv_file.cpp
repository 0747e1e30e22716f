#include "csv_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "usage_error.h"

namespace fooball::cli {

CsvFile::CsvFile(const std::filesystem::path& path, std::string_view flag, std::string_view header)
    : path_(path), flag_(flag), file_(std::fopen(path.c_str(), "w")) {
  if (!file_) {
    throw UsageError(flag_ + " '" + path.string() +
                     "': cannot open for writing: " + std::strerror(errno));
  }
  write(header);
  write("\n");
}

void CsvFile::write(std::string_view row) {
  std::fwrite(row.data(), 1, row.size(), file_.get());
}

void CsvFile::close() {
  const bool writeFailed = std::ferror(file_.get()) != 0;
  // fclose flushes the buffer, so it can be the first call to see a full disk.
  const bool closeFailed = std::fclose(file_.release()) != 0;
  if (writeFailed || closeFailed) {
    throw std::runtime_error(flag_ + " '" + path_.string() +
                             "': writing failed: " + std::strerror(errno));
  }
}

}  // namespace fooball::cli
